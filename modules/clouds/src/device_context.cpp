#include "device_context.h"

#include <utility>

namespace clouds::detail {

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) {
    throw ModuleError(std::string("clouds: ") + what + " failed (VkResult " +
                      std::to_string(static_cast<int>(result)) + ")");
  }
}

DeviceContext::DeviceContext(const CreateInfo& info, const VulkanFunctions& functions)
    : fn_(functions), device_(info.device), physical_(info.physicalDevice) {
  fn_.vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
}

std::uint32_t DeviceContext::memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags wanted) const {
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & wanted) == wanted) {
      return i;
    }
  }
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if (typeBits & (1u << i)) return i;  // no preferred type: any that fits
  }
  throw ModuleError("clouds: no memory type fits a module resource");
}

void DeviceContext::name(VkObjectType type, std::uint64_t handle, const std::string& name) const {
  if (fn_.vkSetDebugUtilsObjectNameEXT == nullptr || handle == 0) return;
  const std::string full = "clouds: " + name;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = full.c_str();
  fn_.vkSetDebugUtilsObjectNameEXT(device_, &info);
}

void DeviceContext::beginLabel(VkCommandBuffer cmd, const char* name) const {
  if (fn_.vkCmdBeginDebugUtilsLabelEXT == nullptr) return;
  VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  label.pLabelName = name;
  fn_.vkCmdBeginDebugUtilsLabelEXT(cmd, &label);
}

void DeviceContext::endLabel(VkCommandBuffer cmd) const {
  if (fn_.vkCmdEndDebugUtilsLabelEXT != nullptr) fn_.vkCmdEndDebugUtilsLabelEXT(cmd);
}

bool DeviceContext::supportsStorage(VkFormat format) const {
  VkFormatProperties properties{};
  fn_.vkGetPhysicalDeviceFormatProperties(physical_, format, &properties);
  return (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT) != 0;
}

OwnedImage::OwnedImage(const DeviceContext& context, VkImageType type, VkFormat format,
                       VkExtent3D extent, VkImageUsageFlags usage, const std::string& name)
    : context_(&context), format_(format), extent_(extent) {
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
  check(fn.vkCreateImage(context.device(), &info, nullptr, &image_), "vkCreateImage");
  context.name(VK_OBJECT_TYPE_IMAGE, bits(image_), name);
  VkMemoryRequirements requirements{};
  fn.vkGetImageMemoryRequirements(context.device(), image_, &requirements);
  VkMemoryAllocateInfo allocation{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocation.allocationSize = requirements.size;
  allocation.memoryTypeIndex =
      context.memoryType(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  check(fn.vkAllocateMemory(context.device(), &allocation, nullptr, &memory_), "vkAllocateMemory");
  context.name(VK_OBJECT_TYPE_DEVICE_MEMORY, bits(memory_), name + " memory");
  check(fn.vkBindImageMemory(context.device(), image_, memory_, 0), "vkBindImageMemory");
  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image_;
  viewInfo.viewType = type == VK_IMAGE_TYPE_3D ? VK_IMAGE_VIEW_TYPE_3D : VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = format;
  viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  check(fn.vkCreateImageView(context.device(), &viewInfo, nullptr, &view_), "vkCreateImageView");
  context.name(VK_OBJECT_TYPE_IMAGE_VIEW, bits(view_), name + " view");
}

OwnedImage& OwnedImage::operator=(OwnedImage&& other) noexcept {
  if (this != &other) {
    reset();
    context_ = std::exchange(other.context_, nullptr);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    format_ = other.format_;
    extent_ = other.extent_;
  }
  return *this;
}

void OwnedImage::reset() {
  if (context_ == nullptr) return;
  const auto& fn = context_->fn();
  if (view_ != VK_NULL_HANDLE) fn.vkDestroyImageView(context_->device(), view_, nullptr);
  if (image_ != VK_NULL_HANDLE) fn.vkDestroyImage(context_->device(), image_, nullptr);
  if (memory_ != VK_NULL_HANDLE) fn.vkFreeMemory(context_->device(), memory_, nullptr);
  context_ = nullptr;
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
}

OwnedBuffer::OwnedBuffer(const DeviceContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                         const std::string& name, bool hostVisible)
    : context_(&context), size_(size) {
  const auto& fn = context.fn();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  check(fn.vkCreateBuffer(context.device(), &info, nullptr, &buffer_), "vkCreateBuffer");
  context.name(VK_OBJECT_TYPE_BUFFER, bits(buffer_), name);
  VkMemoryRequirements requirements{};
  fn.vkGetBufferMemoryRequirements(context.device(), buffer_, &requirements);
  VkMemoryAllocateInfo allocation{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocation.allocationSize = requirements.size;
  allocation.memoryTypeIndex = context.memoryType(
      requirements.memoryTypeBits,
      hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                  : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  check(fn.vkAllocateMemory(context.device(), &allocation, nullptr, &memory_), "vkAllocateMemory");
  context.name(VK_OBJECT_TYPE_DEVICE_MEMORY, bits(memory_), name + " memory");
  check(fn.vkBindBufferMemory(context.device(), buffer_, memory_, 0), "vkBindBufferMemory");
  if (hostVisible) check(fn.vkMapMemory(context.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
}

OwnedBuffer& OwnedBuffer::operator=(OwnedBuffer&& other) noexcept {
  if (this != &other) {
    reset();
    context_ = std::exchange(other.context_, nullptr);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = other.size_;
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

void OwnedBuffer::reset() {
  if (context_ == nullptr) return;
  const auto& fn = context_->fn();
  if (buffer_ != VK_NULL_HANDLE) fn.vkDestroyBuffer(context_->device(), buffer_, nullptr);
  if (memory_ != VK_NULL_HANDLE) fn.vkFreeMemory(context_->device(), memory_, nullptr);
  context_ = nullptr;
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
}

void barrier(const DeviceContext& context, VkCommandBuffer cmd, VkImage image,
             VkImageAspectFlags aspect, VkImageLayout oldLayout, VkImageLayout newLayout,
             VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
             VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = srcStages;
  b.srcAccessMask = srcAccess;
  b.dstStageMask = dstStages;
  b.dstAccessMask = dstAccess;
  b.oldLayout = oldLayout;
  b.newLayout = newLayout;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {aspect, 0, 1, 0, 1};
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &b;
  context.fn().vkCmdPipelineBarrier2(cmd, &dependency);
}

void memoryBarrier(const DeviceContext& context, VkCommandBuffer cmd,
                   VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
  VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  b.srcStageMask = srcStages;
  b.srcAccessMask = srcAccess;
  b.dstStageMask = dstStages;
  b.dstAccessMask = dstAccess;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.memoryBarrierCount = 1;
  dependency.pMemoryBarriers = &b;
  context.fn().vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace clouds::detail
