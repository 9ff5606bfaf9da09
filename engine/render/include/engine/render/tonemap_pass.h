#pragma once
// The display transform as a frame-graph pass: HDR scene -> the present target.
#include "engine/gfx/pipelines.h"
#include "engine/gfx/resources.h"
#include "engine/render/frame_graph.h"

namespace engine::render {

struct TonemapSettings {
  float exposure = 1.0f;  // linear multiplier, > 0
  bool rawHdrView = false;
};

class Tonemapper {
 public:
  // `hdrFormat` is the scene colour format; `targetFormat` the present target's.
  Tonemapper(gfx::Device& device, VkFormat hdrFormat, VkFormat targetFormat);
  const gfx::Pipeline& pipeline() const { return pipeline_; }
  VkSampler sampler() const { return sampler_.vk(); }
  VkFormat targetFormat() const { return targetFormat_; }

 private:
  VkFormat targetFormat_;
  gfx::Sampler sampler_;
  gfx::Pipeline pipeline_;
};

// Adds the "tonemap" pass; `settings` is read when the pass executes (each frame) and must
// outlive the graph. Returns the new version of `target`.
TextureHandle addTonemapPass(FrameGraph& graph, const Tonemapper& tonemapper, TextureHandle hdr,
                             TextureHandle target, const TonemapSettings* settings);

}  // namespace engine::render
