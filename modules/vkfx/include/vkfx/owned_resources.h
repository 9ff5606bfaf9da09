#pragma once
// Images and buffers the module allocates: each an object, its memory and (for images) a view,
// owned from the line each is created, so a failure halfway leaves nothing behind. Destroyed
// immediately when dropped: the Context's destructor contract says the GPU is done with them,
// and images replaced while frames may be in flight go through the module's retire list.
#include <vulkan/vulkan.h>

#include <string>

#include "vkfx/device_context.h"

namespace vkfx {

class OwnedImage {
 public:
  OwnedImage() = default;
  OwnedImage(const DeviceContext& context, VkImageType type, VkFormat format, VkExtent3D extent,
             VkImageUsageFlags usage, const std::string& name);

  VkImage image() const { return image_.get(); }
  VkImageView view() const { return view_.get(); }
  VkFormat format() const { return format_; }
  VkExtent3D extent() const { return extent_; }
  VkDeviceSize bytes() const { return bytes_; }
  explicit operator bool() const { return static_cast<bool>(image_); }

 private:
  // Declaration order is destruction order reversed: the view, then the image, then memory.
  UniqueMemory memory_;
  UniqueImage image_;
  UniqueImageView view_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent3D extent_{};
  VkDeviceSize bytes_ = 0;
};

class OwnedBuffer {
 public:
  OwnedBuffer() = default;
  // `hostVisible`: host-visible, coherent and persistently mapped (mapped() is non-null).
  OwnedBuffer(const DeviceContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
              const std::string& name, bool hostVisible = false);

  VkBuffer buffer() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }
  VkDeviceSize bytes() const { return bytes_; }
  const void* mapped() const { return mapped_; }
  void* mapped() { return mapped_; }

 private:
  UniqueMemory memory_;  // freeing the memory unmaps it
  UniqueBuffer buffer_;
  VkDeviceSize size_ = 0;
  VkDeviceSize bytes_ = 0;
  void* mapped_ = nullptr;
};

}  // namespace vkfx
