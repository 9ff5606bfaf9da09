#pragma once
// The display transform as a frame-graph pass: HDR scene -> the present target.
#include <functional>

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

// Records what is drawn over the tonemapped image in the same render pass (a HUD), with the
// target bound as the colour attachment.
using TonemapOverlay = std::function<void(PassContext&)>;

// Adds the "tonemap" pass; `settings` is read when the pass executes (each frame) and must
// outlive the graph. An `overlay` is recorded after the tonemapping draw and names the pass
// "tonemap + overlay" (on a CPU device a render pass of its own costs ~0.2 ms more).
// Returns the new version of `target`.
TextureHandle addTonemapPass(FrameGraph& graph, const Tonemapper& tonemapper, TextureHandle hdr,
                             TextureHandle target, const TonemapSettings* settings,
                             TonemapOverlay overlay = {});

}  // namespace engine::render
