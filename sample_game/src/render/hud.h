#pragma once
// On-screen frame rate, help and the settings panel: Dear ImGui (Debian's libimgui) lays them
// out (hud_layout.h, settings_panel.h); this records them with one small pipeline of our own
// (ImGui's own Vulkan backend in that version needs a render pass object) into the tonemap
// pass, after its draw (render::TonemapOverlay): a render pass of its own cost ~0.2 ms more
// on lavapipe. Opaque backgrounds are clears (hud_draw_plan.h).
#include <array>
#include <memory>
#include <span>

#include "engine/ecs/world.h"
#include "engine/gfx/frame_ring.h"
#include "engine/gfx/gpu_timer.h"
#include "engine/gfx/pipelines.h"
#include "engine/gfx/resources.h"
#include "engine/render/frame_graph.h"
#include "render/hud_draw_plan.h"

struct ImGuiContext;

namespace sample {

class Hud {
 public:
  // `clearRectangles`: the opaque backgrounds as clears (hud_draw_plan.h); false, as triangles.
  Hud(engine::gfx::Device& device, VkFormat targetFormat, bool clearRectangles = true);
  ~Hud();

  const engine::gfx::Pipeline& pipeline() const { return pipeline_; }
  // Lays out this frame's text and uploads its vertices into the frame slot's buffers.
  void prepare(engine::ecs::World& world, VkExtent2D extent,
               std::span<const engine::gfx::TimedScope> gpuTimings,
               const engine::gfx::FrameRing::Frame& frame);
  void record(VkCommandBuffer cmd, engine::gfx::DescriptorArena& descriptors,
              const engine::gfx::Device& device) const;
  // F1: the help and every pass's time besides the one line (hud_layout.h).
  bool full() const { return full_; }
  bool panelOpen() const { return panelOpen_; }

 private:
  engine::gfx::Device& device_;
  ImGuiContext* context_ = nullptr;
  engine::gfx::Image font_;
  engine::gfx::Sampler sampler_;
  engine::gfx::Pipeline pipeline_;
  struct SlotBuffers {
    engine::gfx::Buffer vertices;
    engine::gfx::Buffer indices;
  };
  std::array<SlotBuffers, engine::gfx::FrameRing::kFramesInFlight> buffers_;
  HudDrawPlan plan_;  // this frame's clears and draws
  bool clearRectangles_;
  std::uint32_t slot_ = 0;
  VkExtent2D extent_{0, 0};
  bool full_ = false;
  bool panelOpen_ = false;  // F2: the settings panel
  double smoothedFrameSeconds_ = 0.0;
};

}  // namespace sample
