#pragma once
// The scene's graphics pass into a new reversed-Z depth buffer: the water beyond the reach of its
// bed, the terrain, the water over its bed (blended by what it lets through; the water writes
// depth, so the clouds after this pass stop at its surface), then the sky of the features that
// draw one (the atmosphere) where the depth is still the far plane, so the sky is shaded only
// where it is seen. Named "scene" when a feature draws the sky into it, and "terrain" when it
// draws over the renderer's own gradient sky.
#include <span>

#include "engine/render/frame_graph.h"
#include "engine/render/render_feature.h"
#include "render/sky_pass.h"
#include "render/terrain_renderer.h"
#include "render/water_renderer.h"

namespace sample {

struct SceneTargets {
  engine::render::TextureHandle hdr;
  engine::render::TextureHandle depth;
};

// What the scene pass draws of its own (either may be null).
struct SceneSurfaces {
  const TerrainRenderer* terrain = nullptr;
  const WaterRenderer* water = nullptr;
};

// `scene.hdr`: the colour to draw over (the gradient sky), or invalid for a new one (cleared;
// every pixel is then a surface's or a feature's sky). The surfaces are hazed with the
// blackboard's fxcontracts::ecs::AerialPerspective when they were made for it (the haze's range
// and slices read when the pass executes), and lit through `sunlight` (TerrainSunlight) when they
// were made shadowed by the clouds. A hazed water reflects the blackboard's
// fxcontracts::ecs::CoveredSkyRadiance in the frames whose `frame` says so, else its SkyRadiance.
SceneTargets addScenePass(engine::render::FrameGraph& graph, SceneSurfaces surfaces,
                          const engine::render::SceneTextures& scene,
                          engine::render::TextureHandle sunlight,
                          std::span<engine::render::RenderFeature* const> skyDrawers,
                          VkFormat hdrFormat, VkFormat depthFormat, const SceneFrameBinding* frame);

}  // namespace sample
