#include "engine/gfx/resources.h"

#include <utility>

#include "engine/core/error.h"
#include "engine/gfx/formats.h"
#include "engine/gfx/vk_check.h"

namespace engine::gfx {

// --- Buffer ------------------------------------------------------------------------------

Buffer::Buffer(Device& device, const BufferDesc& desc) : device_(&device), size_(desc.sizeBytes) {
  require(desc.sizeBytes > 0, "Buffer '" + desc.debugName + "'", "size must be > 0");
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = desc.sizeBytes;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  GFX_CHECK(vkCreateBuffer(device.vk(), &info, nullptr, &buffer_));
  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(device.vk(), buffer_, &requirements);
  try {
    allocation_ = device.memory().allocate(requirements, desc.memory, ResourceTiling::Linear,
                                           desc.debugName.c_str());
  } catch (...) {
    vkDestroyBuffer(device.vk(), buffer_, nullptr);
    throw;
  }
  GFX_CHECK(vkBindBufferMemory(device.vk(), buffer_, allocation_.memory, allocation_.offset));
  setName(device, buffer_, desc.debugName.c_str());
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, nullptr);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    allocation_ = std::exchange(other.allocation_, Allocation{});
  }
  return *this;
}

void Buffer::reset() {
  if (device_ != nullptr && buffer_ != VK_NULL_HANDLE) {
    device_->release(VK_OBJECT_TYPE_BUFFER, handleBits(buffer_), allocation_);
  }
  device_ = nullptr;
  buffer_ = VK_NULL_HANDLE;
  allocation_ = {};
  size_ = 0;
}

// --- Image -------------------------------------------------------------------------------

VkImageViewType defaultViewType(VkImageType type, std::uint32_t arrayLayers) {
  switch (type) {
    case VK_IMAGE_TYPE_1D:
      return arrayLayers > 1 ? VK_IMAGE_VIEW_TYPE_1D_ARRAY : VK_IMAGE_VIEW_TYPE_1D;
    case VK_IMAGE_TYPE_3D:
      return VK_IMAGE_VIEW_TYPE_3D;
    default:
      return arrayLayers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  }
}

Image::Image(Device& device, const ImageDesc& desc) : device_(&device), desc_(desc) {
  const std::string context = "Image '" + desc.debugName + "'";
  require(desc.extent.width > 0 && desc.extent.height > 0 && desc.extent.depth > 0, context,
          "extent must be non-zero");
  require(desc.usage != 0, context, "usage must not be empty");
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = desc.type;
  info.format = desc.format;
  info.extent = desc.extent;
  info.mipLevels = desc.mipLevels;
  info.arrayLayers = desc.arrayLayers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  GFX_CHECK(vkCreateImage(device.vk(), &info, nullptr, &image_));
  // The destructor does not run for a constructor that throws: what exists goes back here.
  try {
    createMemoryAndView();
  } catch (...) {
    reset();
    throw;
  }
}

void Image::createMemoryAndView() {
  Device& device = *device_;
  const ImageDesc& desc = desc_;
  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(device.vk(), image_, &requirements);
  allocation_ = device.memory().allocate(requirements, MemoryUsage::GpuOnly,
                                         ResourceTiling::Optimal, desc.debugName.c_str());
  GFX_CHECK(vkBindImageMemory(device.vk(), image_, allocation_.memory, allocation_.offset));
  setName(device, image_, desc.debugName.c_str());

  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image_;
  viewInfo.viewType = defaultViewType(desc.type, desc.arrayLayers);
  viewInfo.format = desc.format;
  viewInfo.subresourceRange = fullRange();
  // A depth+stencil view cannot be sampled; the default view covers depth only.
  if (hasStencil(desc.format)) viewInfo.subresourceRange.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
  GFX_CHECK(vkCreateImageView(device.vk(), &viewInfo, nullptr, &view_));
  setName(device, view_, (desc.debugName + " view").c_str());
}

VkImageSubresourceRange Image::fullRange() const {
  return VkImageSubresourceRange{aspectMask(desc_.format), 0, desc_.mipLevels, 0,
                                 desc_.arrayLayers};
}

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, nullptr);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    allocation_ = std::exchange(other.allocation_, Allocation{});
    desc_ = std::move(other.desc_);
  }
  return *this;
}

void Image::reset() {
  if (device_ != nullptr && image_ != VK_NULL_HANDLE) {
    device_->release(VK_OBJECT_TYPE_IMAGE_VIEW, handleBits(view_));
    device_->release(VK_OBJECT_TYPE_IMAGE, handleBits(image_), allocation_);
  }
  device_ = nullptr;
  image_ = VK_NULL_HANDLE;
  view_ = VK_NULL_HANDLE;
  allocation_ = {};
}

// --- ImageView ---------------------------------------------------------------------------

ImageView::ImageView(Device& device, const Image& image, const ImageViewDesc& desc)
    : device_(&device) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image.vk();
  info.viewType = desc.type;
  info.format = desc.format == VK_FORMAT_UNDEFINED ? image.format() : desc.format;
  info.subresourceRange = desc.range;
  GFX_CHECK(vkCreateImageView(device.vk(), &info, nullptr, &view_));
  setName(device, view_, desc.debugName.c_str());
}

ImageView& ImageView::operator=(ImageView&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, nullptr);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
  }
  return *this;
}

void ImageView::reset() {
  if (device_ != nullptr && view_ != VK_NULL_HANDLE) {
    device_->release(VK_OBJECT_TYPE_IMAGE_VIEW, handleBits(view_));
  }
  device_ = nullptr;
  view_ = VK_NULL_HANDLE;
}

// --- Sampler -----------------------------------------------------------------------------

Sampler::Sampler(Device& device, const SamplerDesc& desc) : device_(&device) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = desc.filter;
  info.minFilter = desc.filter;
  info.mipmapMode = desc.mipmapMode;
  info.addressModeU = desc.addressMode;
  info.addressModeV = desc.addressMode;
  info.addressModeW = desc.addressMode;
  info.maxLod = VK_LOD_CLAMP_NONE;
  GFX_CHECK(vkCreateSampler(device.vk(), &info, nullptr, &sampler_));
  setName(device, sampler_, desc.debugName.c_str());
}

Sampler& Sampler::operator=(Sampler&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, nullptr);
    sampler_ = std::exchange(other.sampler_, VK_NULL_HANDLE);
  }
  return *this;
}

void Sampler::reset() {
  if (device_ != nullptr && sampler_ != VK_NULL_HANDLE) {
    device_->release(VK_OBJECT_TYPE_SAMPLER, handleBits(sampler_));
  }
  device_ = nullptr;
  sampler_ = VK_NULL_HANDLE;
}

}  // namespace engine::gfx
