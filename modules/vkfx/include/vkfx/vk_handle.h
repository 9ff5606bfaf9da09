#pragma once
// Move-only owners of the module's Vulkan objects. Every object the module creates is wrapped
// in one on the line that creates it (DeviceContext's create* functions), so an exception
// thrown by any later step of a constructor destroys what was made before it: no leak when
// creation fails halfway, and no hand-written destructors.
#include <vulkan/vulkan.h>

#include <utility>

#include "vkfx/vulkan_functions.h"

namespace vkfx {

// `Destroy` is the VulkanFunctions member that destroys a `Handle`: every vkDestroy* and
// vkFreeMemory has the shape (VkDevice, Handle, const VkAllocationCallbacks*).
template <typename HandleType, auto Destroy>
class UniqueHandle {
 public:
  using Handle = HandleType;
  UniqueHandle() = default;
  UniqueHandle(const VulkanFunctions& fn, VkDevice device, Handle handle)
      : fn_(&fn), device_(device), handle_(handle) {}
  ~UniqueHandle() { reset(); }
  UniqueHandle(UniqueHandle&& other) noexcept
      : fn_(other.fn_), device_(other.device_), handle_(std::exchange(other.handle_, Handle{})) {}
  UniqueHandle& operator=(UniqueHandle&& other) noexcept {
    if (this != &other) {
      reset();
      fn_ = other.fn_;
      device_ = other.device_;
      handle_ = std::exchange(other.handle_, Handle{});
    }
    return *this;
  }
  UniqueHandle(const UniqueHandle&) = delete;
  UniqueHandle& operator=(const UniqueHandle&) = delete;

  Handle get() const { return handle_; }
  explicit operator bool() const { return handle_ != Handle{}; }
  void reset() {
    if (handle_ != Handle{}) (fn_->*Destroy)(device_, std::exchange(handle_, Handle{}), nullptr);
  }

 private:
  const VulkanFunctions* fn_ = nullptr;
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_{};
};

using UniqueImage = UniqueHandle<VkImage, &VulkanFunctions::vkDestroyImage>;
using UniqueImageView = UniqueHandle<VkImageView, &VulkanFunctions::vkDestroyImageView>;
using UniqueBuffer = UniqueHandle<VkBuffer, &VulkanFunctions::vkDestroyBuffer>;
using UniqueMemory = UniqueHandle<VkDeviceMemory, &VulkanFunctions::vkFreeMemory>;
using UniqueSampler = UniqueHandle<VkSampler, &VulkanFunctions::vkDestroySampler>;
using UniqueShaderModule = UniqueHandle<VkShaderModule, &VulkanFunctions::vkDestroyShaderModule>;
using UniqueSetLayout =
    UniqueHandle<VkDescriptorSetLayout, &VulkanFunctions::vkDestroyDescriptorSetLayout>;
using UniquePipelineLayout =
    UniqueHandle<VkPipelineLayout, &VulkanFunctions::vkDestroyPipelineLayout>;
using UniquePipeline = UniqueHandle<VkPipeline, &VulkanFunctions::vkDestroyPipeline>;
using UniqueDescriptorPool =
    UniqueHandle<VkDescriptorPool, &VulkanFunctions::vkDestroyDescriptorPool>;
using UniqueQueryPool = UniqueHandle<VkQueryPool, &VulkanFunctions::vkDestroyQueryPool>;

}  // namespace vkfx
