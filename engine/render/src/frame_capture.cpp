#include "engine/render/frame_capture.h"

#include <glm/gtc/packing.hpp>

#include <cstring>

#include "engine/core/error.h"
#include "engine/gfx/formats.h"

namespace engine::render {

FrameCapture::FrameCapture(gfx::Device& device) : device_(device) {}

void FrameCapture::ensureBuffers(VkExtent2D extent, VkFormat displayFormat, VkFormat hdrFormat) {
  if (extent.width == extent_.width && extent.height == extent_.height &&
      displayFormat == displayFormat_ && hdrFormat == hdrFormat_) {
    return;
  }
  const VkDeviceSize pixels = VkDeviceSize{extent.width} * extent.height;
  displayBuffer_ =
      gfx::Buffer(device_, gfx::BufferDesc{pixels * gfx::texelBytes(displayFormat),
                                           VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                           gfx::MemoryUsage::Readback, "capture display readback"});
  hdrBuffer_ =
      gfx::Buffer(device_, gfx::BufferDesc{pixels * gfx::texelBytes(hdrFormat),
                                           VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                           gfx::MemoryUsage::Readback, "capture hdr readback"});
  extent_ = extent;
  displayFormat_ = displayFormat;
  hdrFormat_ = hdrFormat;
}

void FrameCapture::addToGraph(FrameGraph& graph, TextureHandle hdr, TextureHandle display) {
  const TextureDesc& displayDesc = graph.textureDesc(display);
  const TextureDesc& hdrDesc = graph.textureDesc(hdr);
  require(displayDesc.extent.width == hdrDesc.extent.width &&
              displayDesc.extent.height == hdrDesc.extent.height,
          "FrameCapture", "display and HDR images differ in size");
  ensureBuffers({displayDesc.extent.width, displayDesc.extent.height}, displayDesc.format,
                hdrDesc.format);
  const ResourceState hostRead{VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_HOST_BIT,
                               VK_ACCESS_2_HOST_READ_BIT};
  const BufferHandle displayBuffer = graph.importBuffer(
      "capture display buffer",
      ImportedBuffer{displayBuffer_.vk(), displayBuffer_.size(), hostRead, hostRead});
  const BufferHandle hdrBuffer = graph.importBuffer(
      "capture hdr buffer", ImportedBuffer{hdrBuffer_.vk(), hdrBuffer_.size(), hostRead, hostRead});

  struct Data {
    TextureHandle hdr, display;
    BufferHandle hdrBuffer, displayBuffer;
  };
  graph.addPass<Data>(
      "capture", PassType::Transfer,
      [&](PassBuilder& builder, Data& d) {
        d.hdr = builder.read(hdr, Access::TransferSrc);
        d.display = builder.read(display, Access::TransferSrc);
        d.hdrBuffer = builder.write(hdrBuffer, Access::TransferDst);
        d.displayBuffer = builder.write(displayBuffer, Access::TransferDst);
        builder.sideEffect();
      },
      [this](const Data& d, PassContext& context) {
        if (!armed_) return;  // the copies only run on captured frames
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent_.width, extent_.height, 1};
        vkCmdCopyImageToBuffer(context.cmd(), context.image(d.display),
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               context.buffer(d.displayBuffer), 1, &region);
        vkCmdCopyImageToBuffer(context.cmd(), context.image(d.hdr),
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, context.buffer(d.hdrBuffer), 1,
                               &region);
        inFlight_ = std::move(armed_);
        armed_.reset();
      });
}

void FrameCapture::arm(std::filesystem::path stem) {
  armed_ = std::move(stem);
}

std::optional<std::filesystem::path> FrameCapture::writePending() {
  if (!inFlight_) return std::nullopt;
  const std::size_t pixels = std::size_t{extent_.width} * extent_.height;

  display_.width = extent_.width;
  display_.height = extent_.height;
  display_.pixels.resize(pixels * 4);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(displayBuffer_.mapped());
  const bool bgra =
      displayFormat_ == VK_FORMAT_B8G8R8A8_SRGB || displayFormat_ == VK_FORMAT_B8G8R8A8_UNORM;
  for (std::size_t i = 0; i < pixels; ++i) {
    display_.pixels[4 * i + 0] = bytes[4 * i + (bgra ? 2 : 0)];
    display_.pixels[4 * i + 1] = bytes[4 * i + 1];
    display_.pixels[4 * i + 2] = bytes[4 * i + (bgra ? 0 : 2)];
    display_.pixels[4 * i + 3] = 255;  // the display is opaque
  }

  hdr_.width = extent_.width;
  hdr_.height = extent_.height;
  hdr_.pixels.resize(pixels * 4);
  if (hdrFormat_ == VK_FORMAT_R16G16B16A16_SFLOAT) {
    const auto* halves = reinterpret_cast<const std::uint16_t*>(hdrBuffer_.mapped());
    for (std::size_t i = 0; i < pixels * 4; ++i) hdr_.pixels[i] = glm::unpackHalf1x16(halves[i]);
  } else if (hdrFormat_ == VK_FORMAT_R32G32B32A32_SFLOAT) {
    std::memcpy(hdr_.pixels.data(), hdrBuffer_.mapped(), pixels * 4 * sizeof(float));
  } else {
    throw Error("FrameCapture: unsupported HDR format " + std::to_string(hdrFormat_));
  }

  std::filesystem::path png = *inFlight_;
  png += ".png";
  std::filesystem::path exr = *inFlight_;
  exr += ".exr";
  assets::writePng(png, display_);
  assets::writeExr(exr, hdr_);
  inFlight_.reset();
  return png;
}

}  // namespace engine::render
