#pragma once
// A window target for software Vulkan devices: the frame is drawn into an offscreen image, read
// back, and put into the window through MIT-SHM (platform::ShmBlitter) instead of Vulkan's
// swapchain. On lavapipe over a server without DRI3 (Xvfb) Mesa's WSI sends every frame
// through the X socket, and that server's copy took 4.1 ms of CPU a frame at 640x360 on the
// 2-core machine, whose CPU is also the device (docs/measurements.md). A device with its own
// memory gains nothing from this: use SwapchainTarget there.
//
// Like a software WSI's present, present() waits for the frame to finish rendering. There is no
// vertical-blank sync (Mesa's software X11 present has none either).
#include <memory>

#include "engine/gfx/device.h"
#include "engine/gfx/resources.h"
#include "engine/platform/shm_blitter.h"
#include "engine/render/present_target.h"

namespace engine::render {

class ShmWindowTarget final : public PresentTarget {
 public:
  ShmWindowTarget(gfx::Device& device, std::unique_ptr<platform::ShmBlitter> blitter);
  VkFormat format() const override { return kFormat; }
  VkExtent2D extent() const override { return frame_ ? frame_->extent() : VkExtent2D{0, 0}; }
  bool acquire(std::uint32_t frameSlot) override;
  VkImage image() const override { return frame_ ? frame_->image() : VK_NULL_HANDLE; }
  VkImageView view() const override { return frame_ ? frame_->view() : VK_NULL_HANDLE; }
  ImportedTexture describe() const override {
    return frame_ ? frame_->describe() : ImportedTexture{};
  }
  std::span<const VkSemaphoreSubmitInfo> submitWaits() const override { return {}; }
  std::span<const VkSemaphoreSubmitInfo> submitSignals() const override { return {}; }
  void present() override;
  void resize(VkExtent2D framebufferExtent) override { wanted_ = framebufferExtent; }
  void addToGraph(FrameGraph& graph, TextureHandle image) override;
  const platform::ShmBlitter& blitter() const { return *blitter_; }

  // The byte order of an X server's 24-bit little-endian visual (B, G, R, unused).
  static constexpr VkFormat kFormat = VK_FORMAT_B8G8R8A8_SRGB;

 private:
  gfx::Device& device_;
  std::unique_ptr<platform::ShmBlitter> blitter_;
  std::unique_ptr<OffscreenTarget> frame_;  // what the frame graph draws, at the window's size
  gfx::Buffer readback_;                    // the drawn frame, copied by the graph's last pass
  VkExtent2D wanted_{0, 0};
  bool drawn_ = false;  // a frame was acquired and is waiting for present()
};

}  // namespace engine::render
