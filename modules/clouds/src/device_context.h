#pragma once
// The module's view of the host device: function table, memory types, debug names, and small
// move-only owners for the images and buffers the module allocates (destroyed immediately:
// the Context's destructor contract says the GPU is done with them).
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

#include "vulkan_functions.h"

namespace clouds::detail {

// Thrown inside the module on Vulkan failures and caught at the public API boundary, which
// reports it through the `error` out-parameter (the public API does not throw).
class ModuleError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void check(VkResult result, const char* what);

class DeviceContext {
 public:
  DeviceContext(const CreateInfo& info, const VulkanFunctions& functions);

  const VulkanFunctions& fn() const { return fn_; }
  VkDevice device() const { return device_; }
  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags wanted) const;
  void name(VkObjectType type, std::uint64_t handle, const std::string& name) const;
  void beginLabel(VkCommandBuffer cmd, const char* name) const;
  void endLabel(VkCommandBuffer cmd) const;
  bool supportsStorage(VkFormat format) const;

 private:
  VulkanFunctions fn_;
  VkDevice device_;
  VkPhysicalDevice physical_;
  VkPhysicalDeviceMemoryProperties memory_{};
};

template <typename Handle>
std::uint64_t bits(Handle handle) {
  return reinterpret_cast<std::uint64_t>(handle);
}

class OwnedImage {
 public:
  OwnedImage() = default;
  OwnedImage(const DeviceContext& context, VkImageType type, VkFormat format, VkExtent3D extent,
             VkImageUsageFlags usage, const std::string& name);
  ~OwnedImage() { reset(); }
  OwnedImage(OwnedImage&& other) noexcept { *this = std::move(other); }
  OwnedImage& operator=(OwnedImage&& other) noexcept;
  OwnedImage(const OwnedImage&) = delete;
  OwnedImage& operator=(const OwnedImage&) = delete;
  void reset();

  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }
  VkFormat format() const { return format_; }
  VkExtent3D extent() const { return extent_; }

 private:
  const DeviceContext* context_ = nullptr;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent3D extent_{};
};

class OwnedBuffer {
 public:
  OwnedBuffer() = default;
  // `hostVisible`: host-visible, coherent and persistently mapped (mapped() is non-null).
  OwnedBuffer(const DeviceContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
              const std::string& name, bool hostVisible = false);
  ~OwnedBuffer() { reset(); }
  OwnedBuffer(OwnedBuffer&& other) noexcept { *this = std::move(other); }
  OwnedBuffer& operator=(OwnedBuffer&& other) noexcept;
  OwnedBuffer(const OwnedBuffer&) = delete;
  OwnedBuffer& operator=(const OwnedBuffer&) = delete;
  void reset();

  VkBuffer buffer() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  const void* mapped() const { return mapped_; }

 private:
  const DeviceContext* context_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

// One image barrier in GENERAL layout or a transition, for compute-only module work.
void barrier(const DeviceContext& context, VkCommandBuffer cmd, VkImage image,
             VkImageAspectFlags aspect, VkImageLayout oldLayout, VkImageLayout newLayout,
             VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
             VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);
void memoryBarrier(const DeviceContext& context, VkCommandBuffer cmd,
                   VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);

}  // namespace clouds::detail
