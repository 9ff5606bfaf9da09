#include "vkfx/owned_resources.h"

namespace vkfx {

OwnedImage::OwnedImage(const DeviceContext& context, VkImageType type, VkFormat format,
                       VkExtent3D extent, VkImageUsageFlags usage, const std::string& name)
    : format_(format), extent_(extent) {
  const auto& fn = context.fn();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = type;
  info.format = format;
  info.extent = extent;
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  image_ = context.createImage(info, name);

  VkMemoryRequirements requirements{};
  fn.vkGetImageMemoryRequirements(context.device(), image_.get(), &requirements);
  memory_ = context.allocateFor(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name);
  bytes_ = requirements.size;
  check(fn.vkBindImageMemory(context.device(), image_.get(), memory_.get(), 0),
        "vkBindImageMemory");

  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image_.get();
  viewInfo.viewType = type == VK_IMAGE_TYPE_3D ? VK_IMAGE_VIEW_TYPE_3D : VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = format;
  viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  view_ = context.createImageView(viewInfo, name + " view");
}

OwnedBuffer::OwnedBuffer(const DeviceContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                         const std::string& name, bool hostVisible)
    : size_(size) {
  const auto& fn = context.fn();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  buffer_ = context.createBuffer(info, name);

  VkMemoryRequirements requirements{};
  fn.vkGetBufferMemoryRequirements(context.device(), buffer_.get(), &requirements);
  memory_ = context.allocateFor(
      requirements,
      hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                  : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
      name);
  bytes_ = requirements.size;
  check(fn.vkBindBufferMemory(context.device(), buffer_.get(), memory_.get(), 0),
        "vkBindBufferMemory");
  if (hostVisible) {
    check(fn.vkMapMemory(context.device(), memory_.get(), 0, VK_WHOLE_SIZE, 0, &mapped_),
          "vkMapMemory");
  }
}

}  // namespace vkfx
