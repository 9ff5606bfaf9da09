#include "engine/render/shm_window_target.h"

#include <cstring>
#include <utility>

#include "engine/gfx/formats.h"
#include "engine/gfx/vk_check.h"

namespace engine::render {

ShmWindowTarget::ShmWindowTarget(gfx::Device& device, std::unique_ptr<platform::ShmBlitter> blitter)
    : device_(device), blitter_(std::move(blitter)) {}

bool ShmWindowTarget::acquire(std::uint32_t) {
  drawn_ = false;
  if (wanted_.width == 0 || wanted_.height == 0) return false;  // minimized
  const VkExtent2D current = extent();
  if (current.width != wanted_.width || current.height != wanted_.height) {
    vkDeviceWaitIdle(device_.vk());  // frames in flight may still read the old image
    frame_ = std::make_unique<OffscreenTarget>(device_, wanted_, kFormat);
    readback_ = gfx::Buffer(
        device_,
        gfx::BufferDesc{VkDeviceSize{wanted_.width} * wanted_.height * gfx::texelBytes(kFormat),
                        VK_BUFFER_USAGE_TRANSFER_DST_BIT, gfx::MemoryUsage::Readback,
                        "shm window readback"});
  }
  drawn_ = true;
  return true;
}

void ShmWindowTarget::addToGraph(FrameGraph& graph, TextureHandle image) {
  const ResourceState hostRead{VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_HOST_BIT,
                               VK_ACCESS_2_HOST_READ_BIT};
  const BufferHandle readback = graph.importBuffer(
      "shm window readback", ImportedBuffer{readback_.vk(), readback_.size(), hostRead, hostRead});
  struct Data {
    TextureHandle image;
    BufferHandle readback;
  };
  graph.addPass<Data>(
      "window readback", PassType::Transfer,
      [&](PassBuilder& builder, Data& d) {
        d.image = builder.read(image, Access::TransferSrc);
        d.readback = builder.write(readback, Access::TransferDst);
        builder.sideEffect();
      },
      [this](const Data& d, PassContext& context) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {frame_->extent().width, frame_->extent().height, 1};
        vkCmdCopyImageToBuffer(context.cmd(), context.image(d.image),
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, context.buffer(d.readback), 1,
                               &region);
      });
}

void ShmWindowTarget::present() {
  if (!std::exchange(drawn_, false)) return;
  // The frame was just submitted: wait for it, as a software WSI's present does.
  GFX_CHECK(vkQueueWaitIdle(device_.queue()));
  const std::span<std::byte> pixels = blitter_->pixels(extent());
  std::memcpy(pixels.data(), readback_.mapped(), pixels.size());
  blitter_->put();
}

}  // namespace engine::render
