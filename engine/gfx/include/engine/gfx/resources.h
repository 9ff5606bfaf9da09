#pragma once
// Move-only RAII wrappers for buffers, images and samplers. Destruction is deferred through
// Device::release until the GPU has finished every frame that could use the object, so
// dropping a resource mid-frame is safe. Every object carries a debug name.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "engine/gfx/device.h"
#include "engine/gfx/memory_allocator.h"

namespace engine::gfx {

struct BufferDesc {
  VkDeviceSize sizeBytes = 0;
  VkBufferUsageFlags usage = 0;
  MemoryUsage memory = MemoryUsage::GpuOnly;
  std::string debugName;
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(Device& device, const BufferDesc& desc);
  ~Buffer() { reset(); }
  Buffer(Buffer&& other) noexcept { *this = std::move(other); }
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  void reset();
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }
  VkBuffer vk() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  // Host pointer for Upload/Readback memory; null for GpuOnly memory.
  std::byte* mapped() const { return allocation_.mapped; }
  template <typename T>
  std::span<T> mappedAs() const {
    return {reinterpret_cast<T*>(allocation_.mapped), static_cast<std::size_t>(size_ / sizeof(T))};
  }

 private:
  Device* device_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  Allocation allocation_;
};

struct ImageDesc {
  VkImageType type = VK_IMAGE_TYPE_2D;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkExtent3D extent{1, 1, 1};
  std::uint32_t mipLevels = 1;
  std::uint32_t arrayLayers = 1;
  VkImageUsageFlags usage = 0;
  std::string debugName;
};

// An image with its memory and a default view over every mip and layer.
class Image {
 public:
  Image() = default;
  Image(Device& device, const ImageDesc& desc);
  ~Image() { reset(); }
  Image(Image&& other) noexcept { *this = std::move(other); }
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  void reset();
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }
  VkImage vk() const { return image_; }
  VkImageView view() const { return view_; }
  VkFormat format() const { return desc_.format; }
  VkExtent3D extent() const { return desc_.extent; }
  const ImageDesc& desc() const { return desc_; }
  VkImageSubresourceRange fullRange() const;

 private:
  void createMemoryAndView();

  Device* device_ = nullptr;
  VkImage image_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  Allocation allocation_;
  ImageDesc desc_;
};

// An extra view of an image (one mip, one layer, another type); the default view comes with
// the Image. The image must outlive the view.
struct ImageViewDesc {
  VkImageViewType type = VK_IMAGE_VIEW_TYPE_2D;
  VkFormat format = VK_FORMAT_UNDEFINED;  // UNDEFINED: the image's format
  VkImageSubresourceRange range{};
  std::string debugName;
};

class ImageView {
 public:
  ImageView() = default;
  ImageView(Device& device, const Image& image, const ImageViewDesc& desc);
  ~ImageView() { reset(); }
  ImageView(ImageView&& other) noexcept { *this = std::move(other); }
  ImageView& operator=(ImageView&& other) noexcept;
  ImageView(const ImageView&) = delete;
  ImageView& operator=(const ImageView&) = delete;

  void reset();
  VkImageView vk() const { return view_; }

 private:
  Device* device_ = nullptr;
  VkImageView view_ = VK_NULL_HANDLE;
};

struct SamplerDesc {
  VkFilter filter = VK_FILTER_LINEAR;
  VkSamplerMipmapMode mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  VkSamplerAddressMode addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  std::string debugName;
};

class Sampler {
 public:
  Sampler() = default;
  Sampler(Device& device, const SamplerDesc& desc);
  ~Sampler() { reset(); }
  Sampler(Sampler&& other) noexcept { *this = std::move(other); }
  Sampler& operator=(Sampler&& other) noexcept;
  Sampler(const Sampler&) = delete;
  Sampler& operator=(const Sampler&) = delete;

  void reset();
  VkSampler vk() const { return sampler_; }

 private:
  Device* device_ = nullptr;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

// Image view type matching an image's type and layer count.
VkImageViewType defaultViewType(VkImageType type, std::uint32_t arrayLayers);

}  // namespace engine::gfx
