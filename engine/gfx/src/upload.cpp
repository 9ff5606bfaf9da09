#include "engine/gfx/upload.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "engine/gfx/formats.h"

namespace engine::gfx {
namespace {

// Mip `level`'s extent: each side halved per level, at least 1.
VkExtent3D mipExtent(const Image& image, std::uint32_t level) {
  const VkExtent3D e = image.extent();
  return {std::max(e.width >> level, 1u), std::max(e.height >> level, 1u),
          std::max(e.depth >> level, 1u)};
}

VkDeviceSize mipBytes(const Image& image, std::uint32_t level) {
  const VkExtent3D e = mipExtent(image, level);
  return VkDeviceSize{texelBytes(image.format())} * e.width * e.height * e.depth;
}

VkBufferImageCopy wholeMip(const Image& image, std::uint32_t level, VkDeviceSize bufferOffset) {
  VkBufferImageCopy region{};
  region.bufferOffset = bufferOffset;
  region.imageSubresource = {
      aspectMask(image.format()) & ~VkImageAspectFlags{VK_IMAGE_ASPECT_STENCIL_BIT}, level, 0, 1};
  region.imageExtent = mipExtent(image, level);
  return region;
}

std::vector<std::byte> readback(Device& device, VkImage source,
                                const VkImageSubresourceRange& range,
                                const VkBufferImageCopy& region, VkDeviceSize bytes,
                                const ImageState& currentState) {
  Buffer staging(device, BufferDesc{bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback,
                                    "staging image readback"});
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, source, range, currentState, kTransferSrc);
    vkCmdCopyImageToBuffer(cmd, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.vk(), 1,
                           &region);
    // Back to the caller's layout; an undefined "current" state has no layout to return to.
    ImageState back = currentState;
    if (back.layout == VK_IMAGE_LAYOUT_UNDEFINED) back = kTransferSrc;
    imageBarrier(cmd, source, range, kTransferSrc, back);
    bufferBarrier(cmd, staging.vk(), VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                  VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                  VK_ACCESS_2_HOST_READ_BIT);
  });
  std::vector<std::byte> out(bytes);
  std::memcpy(out.data(), staging.mapped(), bytes);
  return out;
}

}  // namespace

void uploadToBuffer(Device& device, const Buffer& destination, std::span<const std::byte> data,
                    VkDeviceSize destinationOffset) {
  require(destinationOffset + data.size() <= destination.size(), "uploadToBuffer",
          "data does not fit the destination buffer");
  if (data.empty()) return;
  Buffer staging(device, BufferDesc{data.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                    MemoryUsage::Upload, "staging upload"});
  std::memcpy(staging.mapped(), data.data(), data.size());
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    const VkBufferCopy copy{0, destinationOffset, data.size()};
    vkCmdCopyBuffer(cmd, staging.vk(), destination.vk(), 1, &copy);
    bufferBarrier(cmd, destination.vk(), VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                  VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                  VK_ACCESS_2_MEMORY_READ_BIT);
  });
}

void uploadToImage(Device& device, const Image& destination, std::span<const std::byte> texels,
                   const ImageState& finalState) {
  uploadMipsToImage(device, destination, texels, 1, finalState);
}

void uploadMipsToImage(Device& device, const Image& destination, std::span<const std::byte> texels,
                       std::uint32_t levels, const ImageState& finalState) {
  const std::string what = "uploadMipsToImage '" + destination.desc().debugName + "'";
  require(levels >= 1 && levels <= destination.desc().mipLevels, what,
          std::to_string(levels) + " levels for an image of " +
              std::to_string(destination.desc().mipLevels));
  std::vector<VkBufferImageCopy> regions;
  VkDeviceSize bytes = 0;
  for (std::uint32_t level = 0; level < levels; ++level) {
    regions.push_back(wholeMip(destination, level, bytes));
    bytes += mipBytes(destination, level);
  }
  require(texels.size() == bytes, what,
          "expected " + std::to_string(bytes) + " bytes, got " + std::to_string(texels.size()));
  Buffer staging(device, BufferDesc{bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::Upload,
                                    "staging image upload"});
  std::memcpy(staging.mapped(), texels.data(), texels.size());
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, destination.vk(), destination.fullRange(), kUndefined, kTransferDst);
    vkCmdCopyBufferToImage(cmd, staging.vk(), destination.vk(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           static_cast<std::uint32_t>(regions.size()), regions.data());
    imageBarrier(cmd, destination.vk(), destination.fullRange(), kTransferDst, finalState);
  });
}

std::vector<std::byte> readbackImage(Device& device, const Image& source,
                                     const ImageState& currentState, std::uint32_t level) {
  require(level < source.desc().mipLevels, "readbackImage '" + source.desc().debugName + "'",
          "mip " + std::to_string(level) + " of " + std::to_string(source.desc().mipLevels));
  const VkBufferImageCopy region = wholeMip(source, level, 0);
  return readback(device, source.vk(), source.fullRange(), region, mipBytes(source, level),
                  currentState);
}

std::vector<std::byte> readbackImage(Device& device, VkImage source, VkFormat format,
                                     VkExtent3D extent, const ImageState& currentState) {
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = extent;
  const VkDeviceSize bytes =
      VkDeviceSize{texelBytes(format)} * extent.width * extent.height * extent.depth;
  return readback(device, source, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}, region, bytes,
                  currentState);
}

std::vector<std::byte> readbackBuffer(Device& device, const Buffer& source) {
  Buffer staging(device, BufferDesc{source.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    MemoryUsage::Readback, "staging buffer readback"});
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    bufferBarrier(cmd, source.vk(), VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                  VK_ACCESS_2_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                  VK_ACCESS_2_TRANSFER_READ_BIT);
    const VkBufferCopy copy{0, 0, source.size()};
    vkCmdCopyBuffer(cmd, source.vk(), staging.vk(), 1, &copy);
    bufferBarrier(cmd, staging.vk(), VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                  VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                  VK_ACCESS_2_HOST_READ_BIT);
  });
  std::vector<std::byte> out(source.size());
  std::memcpy(out.data(), staging.mapped(), out.size());
  return out;
}

}  // namespace engine::gfx
