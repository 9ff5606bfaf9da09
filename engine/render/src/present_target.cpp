#include "engine/render/present_target.h"

namespace engine::render {

OffscreenTarget::OffscreenTarget(gfx::Device& device, VkExtent2D extent, VkFormat format)
    : image_(device,
             gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                            format,
                            {extent.width, extent.height, 1},
                            1,
                            1,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                VK_IMAGE_USAGE_SAMPLED_BIT,
                            "offscreen target"}) {}

ImportedTexture OffscreenTarget::describe() const {
  ImportedTexture texture;
  texture.image = image_.vk();
  texture.view = image_.view();
  texture.desc.extent = image_.extent();
  texture.desc.format = image_.format();
  // Every frame overwrites the whole target, so the previous content is not needed.
  texture.initial = ResourceState{};
  return texture;
}

SwapchainTarget::SwapchainTarget(gfx::Device& device, VkSurfaceKHR surface, bool vsync)
    : swapchain_(device, surface, vsync) {}

bool SwapchainTarget::acquire(std::uint32_t frameSlot) {
  current_ = swapchain_.acquire(frameSlot);
  if (!current_) return false;
  wait_.semaphore = current_->acquired;
  wait_.stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  signal_.semaphore = current_->renderFinished;
  signal_.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  return true;
}

ImportedTexture SwapchainTarget::describe() const {
  ImportedTexture texture;
  texture.image = image();
  texture.view = view();
  texture.desc.extent = {swapchain_.extent().width, swapchain_.extent().height, 1};
  texture.desc.format = swapchain_.format();
  // The acquire semaphore wait is at COLOR_ATTACHMENT_OUTPUT: the first use must depend on
  // that stage so the layout transition happens after the image is really ours.
  texture.initial = ResourceState{
      VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_NONE};
  texture.final = ResourceState{VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                                VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_NONE};
  return texture;
}

std::span<const VkSemaphoreSubmitInfo> SwapchainTarget::submitWaits() const {
  return current_ ? std::span<const VkSemaphoreSubmitInfo>(&wait_, 1)
                  : std::span<const VkSemaphoreSubmitInfo>();
}

std::span<const VkSemaphoreSubmitInfo> SwapchainTarget::submitSignals() const {
  return current_ ? std::span<const VkSemaphoreSubmitInfo>(&signal_, 1)
                  : std::span<const VkSemaphoreSubmitInfo>();
}

void SwapchainTarget::present() {
  if (!current_) return;
  swapchain_.present(*current_);
  current_.reset();
}

}  // namespace engine::render
