#pragma once
// The clouds module on the engine: a CloudRenderer owns a clouds::Context created from the
// engine's gfx::Device, and addCloudPasses() puts the module into a frame graph:
//   "clouds"           reads the scene depth, records Context::dispatch (module outputs are
//                      imported into the graph so later passes can read them);
//   "clouds composite" applies them over the HDR scene colour (colour * T + radiance).
// Per-frame camera, sun and time go in frameInputs() before the graph executes.
#include <string>

#include "clouds/clouds.h"
#include "engine/gfx/device.h"
#include "engine/render/frame_graph.h"

namespace clouds::ecs {

class CloudRenderer {
 public:
  static constexpr VkFormat kCompositeFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

  // Throws engine::Error when the module cannot be created on this device.
  CloudRenderer(engine::gfx::Device& device, VkExtent2D maxExtent, VkFormat depthFormat,
                std::uint32_t noiseSeed, std::uint32_t framesInFlight);
  ~CloudRenderer();

  clouds::Context& context() { return *context_; }
  // Read when the passes execute; everything but the command buffer, render extent and
  // depth view, which the passes fill in.
  clouds::FrameInputs& frameInputs() { return inputs_; }
  clouds::Settings& settings() { return settings_; }
  // The last dispatch's error, empty when it succeeded.
  const std::string& lastError() const { return lastError_; }

  // Records the module's frame with frameInputs() completed by these values; on an error the
  // frame has no clouds, the error is logged once and kept in lastError().
  void dispatch(VkCommandBuffer cmd, VkExtent2D extent, VkImageView depth,
                std::uint64_t frameIndex);
  // Applies the last successful dispatch over `color` (GENERAL, STORAGE usage).
  void composite(VkCommandBuffer cmd, VkImageView color, VkExtent2D extent);

 private:
  engine::gfx::Device& device_;
  std::unique_ptr<clouds::Context> context_;
  clouds::FrameInputs inputs_{};
  clouds::Settings settings_{};
  std::string lastError_;
  bool errorReported_ = false;
};

struct CloudPassOutputs {
  engine::render::TextureHandle hdr;       // scene colour with the clouds composited
  engine::render::TextureHandle radiance;  // the module's radiance + transmittance
  engine::render::TextureHandle depth;     // the module's cloud depths
};

// `sceneDepth` is the host depth (sampled; an invalid handle when the scene has no geometry);
// `hdr` the scene colour (RGBA16F, gets STORAGE).
CloudPassOutputs addCloudPasses(engine::render::FrameGraph& graph, CloudRenderer& renderer,
                                engine::render::TextureHandle sceneDepth,
                                engine::render::TextureHandle hdr);

}  // namespace clouds::ecs
