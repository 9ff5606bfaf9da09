#pragma once
// The sample's first passes: a procedural sky gradient (compute) and a test pattern (graphics,
// depth-tested). They prove the compute and graphics paths through the frame graph.
#include "engine/gfx/pipelines.h"
#include "engine/render/frame_graph.h"
#include "first_frame_constants.h"

namespace sample {

struct FirstFrameParams {
  engine::shaders::SkyGradientConstants sky{};
  engine::shaders::TestPatternConstants pattern{};
};

class FirstFramePipelines {
 public:
  FirstFramePipelines(engine::gfx::Device& device, VkFormat hdrFormat, VkFormat depthFormat);
  const engine::gfx::Pipeline& sky() const { return sky_; }
  const engine::gfx::Pipeline& pattern() const { return pattern_; }

 private:
  engine::gfx::Pipeline sky_;
  engine::gfx::Pipeline pattern_;
};

// "sky": creates the scene's HDR colour image and writes every pixel of it.
engine::render::TextureHandle addSkyGradientPass(engine::render::FrameGraph& graph,
                                                 const FirstFramePipelines& pipelines,
                                                 const engine::render::TextureDesc& hdrDesc,
                                                 const FirstFrameParams* params);

struct SceneTargets {
  engine::render::TextureHandle hdr;
  engine::render::TextureHandle depth;
};
// "test pattern": draws into `hdr` with a fresh reversed-Z depth buffer.
SceneTargets addTestPatternPass(engine::render::FrameGraph& graph,
                                const FirstFramePipelines& pipelines,
                                engine::render::TextureHandle hdr, VkFormat depthFormat,
                                const FirstFrameParams* params);

}  // namespace sample
