#include "engine/gfx/swapchain.h"

#include <algorithm>
#include <string>

#include "engine/core/log.h"
#include "engine/gfx/vk_check.h"

namespace engine::gfx {
namespace {

VkSemaphore createBinarySemaphore(Device& device, const std::string& name) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  GFX_CHECK(vkCreateSemaphore(device.vk(), &info, nullptr, &semaphore));
  setName(device, semaphore, name.c_str());
  return semaphore;
}

VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(count);
  vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data());
  // sRGB formats let the hardware encode the tonemapped output.
  for (const auto& f : formats) {
    if ((f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB) &&
        f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
      return f;
    }
  }
  return formats.at(0);
}

}  // namespace

Swapchain::Swapchain(Device& device, VkSurfaceKHR surface, bool vsync)
    : device_(device), surface_(surface), vsync_(vsync) {
  try {
    for (std::uint32_t i = 0; i < kMaxFramesInFlight; ++i) {
      acquired_[i] = createBinarySemaphore(device, "swapchain acquire " + std::to_string(i));
    }
  } catch (...) {
    // The destructor does not run for a constructor that throws: the semaphores made go here.
    for (VkSemaphore made : acquired_) vkDestroySemaphore(device.vk(), made, nullptr);
    throw;
  }
  format_ = chooseFormat(device.physical(), surface).format;
}

Swapchain::~Swapchain() {
  vkDeviceWaitIdle(device_.vk());
  destroyImages();
  if (swapchain_ != VK_NULL_HANDLE) vkDestroySwapchainKHR(device_.vk(), swapchain_, nullptr);
  for (VkSemaphore s : acquired_) vkDestroySemaphore(device_.vk(), s, nullptr);
}

void Swapchain::resize(VkExtent2D framebufferExtent) {
  if (framebufferExtent.width != wantedExtent_.width ||
      framebufferExtent.height != wantedExtent_.height) {
    wantedExtent_ = framebufferExtent;
    stale_ = true;
  }
}

void Swapchain::destroyImages() {
  for (VkImageView view : views_) vkDestroyImageView(device_.vk(), view, nullptr);
  for (VkSemaphore s : renderFinished_) vkDestroySemaphore(device_.vk(), s, nullptr);
  views_.clear();
  renderFinished_.clear();
  images_.clear();
}

void Swapchain::rebuild() {
  // Rebuilds are rare (resize); waiting for idle keeps image and semaphore reuse trivially safe.
  vkDeviceWaitIdle(device_.vk());
  destroyImages();
  stale_ = false;

  VkSurfaceCapabilitiesKHR caps{};
  GFX_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device_.physical(), surface_, &caps));
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == UINT32_MAX) extent = wantedExtent_;
  extent.width = std::clamp(extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
  extent.height = std::clamp(extent.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  if (extent.width == 0 || extent.height == 0 || wantedExtent_.width == 0 ||
      wantedExtent_.height == 0) {
    // Minimized: no swapchain at 0x0. Keep the old handle destroyed and wait for a size.
    if (swapchain_ != VK_NULL_HANDLE) vkDestroySwapchainKHR(device_.vk(), swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
    extent_ = {0, 0};
    return;
  }

  std::uint32_t modeCount = 0;
  vkGetPhysicalDeviceSurfacePresentModesKHR(device_.physical(), surface_, &modeCount, nullptr);
  std::vector<VkPresentModeKHR> modes(modeCount);
  vkGetPhysicalDeviceSurfacePresentModesKHR(device_.physical(), surface_, &modeCount, modes.data());
  VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR;  // always supported
  if (!vsync_) {
    for (VkPresentModeKHR m : modes) {
      if (m == VK_PRESENT_MODE_MAILBOX_KHR || m == VK_PRESENT_MODE_IMMEDIATE_KHR) mode = m;
    }
  }

  const VkSurfaceFormatKHR surfaceFormat = chooseFormat(device_.physical(), surface_);
  std::uint32_t imageCount = std::max(caps.minImageCount + 1, 3u);
  if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = imageCount;
  info.imageFormat = surfaceFormat.format;
  info.imageColorSpace = surfaceFormat.colorSpace;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode = mode;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  GFX_CHECK(vkCreateSwapchainKHR(device_.vk(), &info, nullptr, &created));
  if (swapchain_ != VK_NULL_HANDLE) vkDestroySwapchainKHR(device_.vk(), swapchain_, nullptr);
  swapchain_ = created;
  setName(device_, swapchain_, "swapchain");
  format_ = surfaceFormat.format;
  extent_ = extent;
  ++rebuildCount_;

  std::uint32_t count = 0;
  vkGetSwapchainImagesKHR(device_.vk(), swapchain_, &count, nullptr);
  images_.resize(count);
  vkGetSwapchainImagesKHR(device_.vk(), swapchain_, &count, images_.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::string suffix = " " + std::to_string(i);
    setName(device_, images_[i], ("swapchain image" + suffix).c_str());
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = images_[i];
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format_;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    GFX_CHECK(vkCreateImageView(device_.vk(), &viewInfo, nullptr, &view));
    setName(device_, view, ("swapchain view" + suffix).c_str());
    views_.push_back(view);
    renderFinished_.push_back(createBinarySemaphore(device_, "swapchain present" + suffix));
  }
  log::info("swapchain: " + std::to_string(extent.width) + "x" + std::to_string(extent.height) +
            ", " + std::to_string(count) + " images");
}

std::optional<SwapchainImage> Swapchain::acquire(std::uint32_t frameSlot) {
  if (stale_) rebuild();
  if (swapchain_ == VK_NULL_HANDLE) return std::nullopt;
  const VkSemaphore acquired = acquired_[frameSlot % kMaxFramesInFlight];
  std::uint32_t index = 0;
  const VkResult result =
      vkAcquireNextImageKHR(device_.vk(), swapchain_, UINT64_MAX, acquired, VK_NULL_HANDLE, &index);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) {
    stale_ = true;
    return std::nullopt;
  }
  if (result != VK_SUCCESS && result != VK_SUBOPTIMAL_KHR) {
    throwVulkanError(result, "vkAcquireNextImageKHR", __FILE__, __LINE__);
  }
  if (result == VK_SUBOPTIMAL_KHR) stale_ = true;  // still usable this frame; rebuild next
  return SwapchainImage{images_[index], views_[index], index, acquired, renderFinished_[index]};
}

void Swapchain::present(const SwapchainImage& image) {
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &image.renderFinished;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &image.index;
  const VkResult result = vkQueuePresentKHR(device_.queue(), &info);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) {
    stale_ = true;
  } else if (result != VK_SUCCESS) {
    throwVulkanError(result, "vkQueuePresentKHR", __FILE__, __LINE__);
  }
}

}  // namespace engine::gfx
