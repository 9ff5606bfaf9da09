#pragma once
// Where a frame ends up. Windowed and headless runs share every pass; only the target differs:
// a swapchain image that is presented, or an offscreen image of the same format family that a
// capture pass reads back. "Headless = windowed minus present."
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "engine/gfx/device.h"
#include "engine/gfx/resources.h"
#include "engine/gfx/swapchain.h"
#include "engine/render/frame_graph.h"

namespace engine::render {

class PresentTarget {
 public:
  virtual ~PresentTarget() = default;
  virtual VkFormat format() const = 0;
  virtual VkExtent2D extent() const = 0;
  // Makes this frame's image current. False: nothing to render into this frame (minimized or
  // rebuilding); the caller skips the frame's rendering.
  virtual bool acquire(std::uint32_t frameSlot) = 0;
  virtual VkImage image() const = 0;
  virtual VkImageView view() const = 0;
  // How the frame graph imports the current image (initial and final states).
  virtual ImportedTexture describe() const = 0;
  virtual std::span<const VkSemaphoreSubmitInfo> submitWaits() const = 0;
  virtual std::span<const VkSemaphoreSubmitInfo> submitSignals() const = 0;
  // Swapchain: queue present. Offscreen: nothing.
  virtual void present() = 0;
  // A window's target follows its framebuffer's size (0x0: minimized); an offscreen one keeps
  // the size it was made with.
  virtual void resize(VkExtent2D /*framebufferExtent*/) {}
  // Adds the passes the target needs once the frame's image is drawn (`image`: its handle in
  // the graph). Call on every graph build, after every pass that draws into the image.
  virtual void addToGraph(FrameGraph& /*graph*/, TextureHandle /*image*/) {}
};

class OffscreenTarget final : public PresentTarget {
 public:
  // RGBA8 sRGB like a typical swapchain, so the bytes read back are what a window would show.
  OffscreenTarget(gfx::Device& device, VkExtent2D extent,
                  VkFormat format = VK_FORMAT_R8G8B8A8_SRGB);
  VkFormat format() const override { return image_.format(); }
  VkExtent2D extent() const override { return {image_.extent().width, image_.extent().height}; }
  bool acquire(std::uint32_t) override { return true; }
  VkImage image() const override { return image_.vk(); }
  VkImageView view() const override { return image_.view(); }
  ImportedTexture describe() const override;
  std::span<const VkSemaphoreSubmitInfo> submitWaits() const override { return {}; }
  std::span<const VkSemaphoreSubmitInfo> submitSignals() const override { return {}; }
  void present() override {}

 private:
  gfx::Image image_;
};

class SwapchainTarget final : public PresentTarget {
 public:
  SwapchainTarget(gfx::Device& device, VkSurfaceKHR surface, bool vsync);
  // Call with the window's framebuffer size every frame; a change rebuilds on next acquire.
  void resize(VkExtent2D framebufferExtent) override { swapchain_.resize(framebufferExtent); }
  VkFormat format() const override { return swapchain_.format(); }
  VkExtent2D extent() const override { return swapchain_.extent(); }
  bool acquire(std::uint32_t frameSlot) override;
  VkImage image() const override { return current_ ? current_->image : VK_NULL_HANDLE; }
  VkImageView view() const override { return current_ ? current_->view : VK_NULL_HANDLE; }
  ImportedTexture describe() const override;
  std::span<const VkSemaphoreSubmitInfo> submitWaits() const override;
  std::span<const VkSemaphoreSubmitInfo> submitSignals() const override;
  void present() override;
  const gfx::Swapchain& swapchain() const { return swapchain_; }

 private:
  gfx::Swapchain swapchain_;
  std::optional<gfx::SwapchainImage> current_;
  VkSemaphoreSubmitInfo wait_{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  VkSemaphoreSubmitInfo signal_{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
};

}  // namespace engine::render
