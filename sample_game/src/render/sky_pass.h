#pragma once
// The "sky" pass: creates the scene's HDR colour image and fills it with the sky of the time of
// day (every pixel is written, so nothing needs clearing).
#include "engine/gfx/frame_ring.h"
#include "engine/gfx/pipelines.h"
#include "engine/render/frame_graph.h"
#include "scene_constants.h"

namespace sample {

// The per-frame scene constants, written once per frame into the frame's constant ring and
// read by the sky and terrain passes.
struct SceneFrameBinding {
  engine::shaders::SceneFrame data{};
  engine::gfx::ConstantRing::Slice slice{};  // valid while the frame records
  // The water reflects the clouds' sky light this frame (fxcontracts::ecs::CoveredSkyRadiance:
  // the frames before made it), else the clear sky's map.
  bool reflectsCoveredSky = false;
};

class SkyPass {
 public:
  SkyPass(engine::gfx::Device& device, VkFormat hdrFormat);
  const engine::gfx::Pipeline& pipeline() const { return pipeline_; }

 private:
  engine::gfx::Pipeline pipeline_;
};

engine::render::TextureHandle addSkyPass(engine::render::FrameGraph& graph, const SkyPass& sky,
                                         const engine::render::TextureDesc& hdrDesc,
                                         const SceneFrameBinding* frame);

}  // namespace sample
