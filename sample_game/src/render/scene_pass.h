#pragma once
// The opaque scene's graphics pass: the terrain into a new reversed-Z depth buffer, then the sky
// of the features that draw one (the atmosphere) where the depth is still the far plane, so the
// sky is shaded only where it is seen. Named "scene" when a feature draws the sky into it, and
// "terrain" when it draws over the renderer's own gradient sky.
#include <span>

#include "engine/render/frame_graph.h"
#include "engine/render/render_feature.h"
#include "render/sky_pass.h"
#include "render/terrain_renderer.h"

namespace sample {

struct SceneTargets {
  engine::render::TextureHandle hdr;
  engine::render::TextureHandle depth;
};

// `scene.hdr`: the colour to draw over (the gradient sky), or invalid for a new one (cleared;
// every pixel is then the terrain's or a feature's sky). `terrain` may be null when a feature
// draws the sky. The terrain is hazed with the blackboard's fxcontracts::ecs::AerialPerspective
// when it was made for it (the haze's range and slices read when the pass executes), and lit
// through `sunlight` (TerrainSunlight) when it was made shadowed by the clouds.
SceneTargets addScenePass(engine::render::FrameGraph& graph, const TerrainRenderer* terrain,
                          const engine::render::SceneTextures& scene,
                          engine::render::TextureHandle sunlight,
                          std::span<engine::render::RenderFeature* const> skyDrawers,
                          VkFormat hdrFormat, VkFormat depthFormat, const SceneFrameBinding* frame);

}  // namespace sample
