#pragma once
// A swapchain for a window surface. It handles resize and minimize: a 0x0 framebuffer leaves
// no swapchain (nothing is acquired or presented until the window has a size again), and an
// out-of-date or suboptimal swapchain is recreated on the next acquire.
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/gfx/device.h"

namespace engine::gfx {

struct SwapchainImage {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  std::uint32_t index = 0;
  VkSemaphore acquired = VK_NULL_HANDLE;        // the frame's submission waits on it
  VkSemaphore renderFinished = VK_NULL_HANDLE;  // the frame's submission signals it
};

class Swapchain {
 public:
  static constexpr std::uint32_t kMaxFramesInFlight = 2;

  // `surface` stays owned by the caller (the window) and must outlive the swapchain.
  Swapchain(Device& device, VkSurfaceKHR surface, bool vsync);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // Records the framebuffer size; the swapchain is rebuilt on the next acquire if it changed.
  void resize(VkExtent2D framebufferExtent);
  // Returns nullopt when there is nothing to render into (minimized or being rebuilt); the
  // caller skips the frame. `frameSlot` selects the acquire semaphore.
  std::optional<SwapchainImage> acquire(std::uint32_t frameSlot);
  // Presents the image acquired last; marks the swapchain for rebuild when out of date.
  void present(const SwapchainImage& image);

  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  bool hasImages() const { return swapchain_ != VK_NULL_HANDLE; }
  std::uint32_t rebuildCount() const { return rebuildCount_; }

 private:
  void rebuild();
  void destroyImages();

  Device& device_;
  VkSurfaceKHR surface_;
  bool vsync_;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{0, 0};
  VkExtent2D wantedExtent_{0, 0};
  bool stale_ = true;
  std::uint32_t rebuildCount_ = 0;
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkSemaphore> renderFinished_;  // one per image: present may still hold it
  std::array<VkSemaphore, kMaxFramesInFlight> acquired_{};
};

}  // namespace engine::gfx
