#include "engine/gfx/deferred_release.h"

#include <algorithm>

#include "engine/core/log.h"

namespace engine::gfx {

void DeferredReleaseQueue::push(VkObjectType type, std::uint64_t handle,
                                const Allocation& allocation, std::uint64_t retireValue) {
  if (handle == 0 && !allocation.valid()) return;
  entries_.push_back(Entry{type, handle, allocation, retireValue});
}

void DeferredReleaseQueue::collect(std::uint64_t completedValue, VkDevice device,
                                   MemoryAllocator& memory) {
  // Stable partition keeps release order for entries that share a retire value (views before
  // their images, pipelines before their layouts), matching the order callers released them.
  const auto ready = std::stable_partition(entries_.begin(), entries_.end(), [&](const Entry& e) {
    return e.retireValue <= completedValue;
  });
  for (auto it = entries_.begin(); it != ready; ++it) destroy(*it, device, memory);
  entries_.erase(entries_.begin(), ready);
}

void DeferredReleaseQueue::destroy(const Entry& entry, VkDevice device, MemoryAllocator& memory) {
  const std::uint64_t h = entry.handle;
  switch (entry.type) {
    case VK_OBJECT_TYPE_UNKNOWN:
      break;  // memory only
    case VK_OBJECT_TYPE_BUFFER:
      vkDestroyBuffer(device, reinterpret_cast<VkBuffer>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_IMAGE:
      vkDestroyImage(device, reinterpret_cast<VkImage>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_IMAGE_VIEW:
      vkDestroyImageView(device, reinterpret_cast<VkImageView>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_SAMPLER:
      vkDestroySampler(device, reinterpret_cast<VkSampler>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_PIPELINE:
      vkDestroyPipeline(device, reinterpret_cast<VkPipeline>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_PIPELINE_LAYOUT:
      vkDestroyPipelineLayout(device, reinterpret_cast<VkPipelineLayout>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT:
      vkDestroyDescriptorSetLayout(device, reinterpret_cast<VkDescriptorSetLayout>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_DESCRIPTOR_POOL:
      vkDestroyDescriptorPool(device, reinterpret_cast<VkDescriptorPool>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_QUERY_POOL:
      vkDestroyQueryPool(device, reinterpret_cast<VkQueryPool>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_SEMAPHORE:
      vkDestroySemaphore(device, reinterpret_cast<VkSemaphore>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_SWAPCHAIN_KHR:
      vkDestroySwapchainKHR(device, reinterpret_cast<VkSwapchainKHR>(h), nullptr);
      break;
    default:
      log::error("DeferredReleaseQueue: object type " + std::to_string(entry.type) +
                 " has no destroy function; leaked");
      break;
  }
  memory.free(entry.allocation);
}

}  // namespace engine::gfx
