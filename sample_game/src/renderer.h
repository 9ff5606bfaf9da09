#pragma once
// The sample's renderer: builds the frame graph for the present target's size, fills the
// per-frame parameters from the world and records, submits and presents one frame. It is the
// same object headless and windowed; only the PresentTarget differs.
#include <memory>

#include "engine/ecs/world.h"
#include "engine/gfx/device.h"
#include "engine/gfx/frame_ring.h"
#include "engine/render/frame_capture.h"
#include "engine/render/frame_graph.h"
#include "engine/render/present_target.h"
#include "engine/render/tonemap_pass.h"
#include "clouds/ecs/cloud_renderer.h"
#include "first_frame_passes.h"

namespace sample {

class Renderer {
 public:
  static constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  // `maxExtent` bounds the render size (windows larger than it are rejected by the clouds).
  Renderer(engine::gfx::Device& device, engine::render::PresentTarget& target,
           VkExtent2D maxExtent);
  ~Renderer();

  // Records and submits the frame for the world's current state. Skips rendering (but keeps
  // the frame ring consistent) when the target has nothing to render into.
  void renderFrame(engine::ecs::World& world);
  // Waits for every frame in flight and writes any pending capture.
  void finish();

  std::vector<const char*> passNames() const;
  std::span<const engine::gfx::TimedScope> lastGpuTimings() const { return ring_.lastTimings(); }
  const engine::render::FrameCapture& capture() const { return capture_; }

 private:
  void rebuildGraph(VkExtent2D extent);
  void updateParams(engine::ecs::World& world, VkExtent2D extent);

  engine::gfx::Device& device_;
  engine::render::PresentTarget& target_;
  engine::gfx::FrameRing ring_;
  engine::render::Tonemapper tonemapper_;
  FirstFramePipelines firstFrame_;
  clouds::ecs::CloudRenderer clouds_;
  engine::render::FrameCapture capture_;
  std::unique_ptr<engine::render::FrameGraph> graph_;
  engine::render::TextureHandle targetHandle_;
  VkExtent2D graphExtent_{0, 0};
  FirstFrameParams params_{};
  engine::render::TonemapSettings tonemap_{};
};

}  // namespace sample
