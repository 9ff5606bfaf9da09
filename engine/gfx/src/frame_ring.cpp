#include "engine/gfx/frame_ring.h"

#include <algorithm>

#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/gfx/vk_check.h"

namespace engine::gfx {

ConstantRing::ConstantRing(Device& device, VkDeviceSize capacityBytes, const std::string& debugName)
    : buffer_(device,
              BufferDesc{capacityBytes,
                         VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                         MemoryUsage::Upload, debugName}),
      alignment_(
          std::max<VkDeviceSize>(device.properties().limits.minUniformBufferOffsetAlignment,
                                 device.properties().limits.minStorageBufferOffsetAlignment)) {}

ConstantRing::Slice ConstantRing::allocate(VkDeviceSize bytes) {
  const VkDeviceSize offset = (head_ + alignment_ - 1) / alignment_ * alignment_;
  if (offset + bytes > buffer_.size()) {
    throw Error("ConstantRing: per-frame constants exceed " + std::to_string(buffer_.size()) +
                " bytes");
  }
  head_ = offset + bytes;
  return Slice{buffer_.vk(), offset, bytes, buffer_.mapped() + offset};
}

FrameRing::FrameRing(Device& device) : device_(device) {
  try {
    createSlots();
  } catch (...) {
    // The destructor does not run for a constructor that throws; the slots' other members go
    // with the slots, the pools (and their command buffers) here.
    for (Slot& slot : slots_) vkDestroyCommandPool(device.vk(), slot.pool, nullptr);
    throw;
  }
}

void FrameRing::createSlots() {
  Device& device = device_;
  for (std::uint32_t i = 0; i < kFramesInFlight; ++i) {
    Slot& slot = slots_[i];
    const std::string suffix = " (frame slot " + std::to_string(i) + ")";
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = device.queueFamily();
    GFX_CHECK(vkCreateCommandPool(device.vk(), &poolInfo, nullptr, &slot.pool));
    setName(device, slot.pool, ("frame command pool" + suffix).c_str());
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = slot.pool;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 1;
    GFX_CHECK(vkAllocateCommandBuffers(device.vk(), &allocInfo, &slot.cmd));
    setName(device, slot.cmd, ("frame commands" + suffix).c_str());
    slot.descriptors = std::make_unique<DescriptorArena>(device, "frame descriptors" + suffix);
    slot.timer =
        std::make_unique<GpuTimer>(device, kMaxTimedScopes, ("frame timestamps" + suffix).c_str());
    slot.constants =
        std::make_unique<ConstantRing>(device, VkDeviceSize{1} << 20, "frame constants" + suffix);
  }
}

FrameRing::~FrameRing() {
  // A destructor must not throw: a device lost only now is reported and teardown goes on
  // (the device then counts every frame as finished).
  try {
    drain();
  } catch (const Error& error) {
    log::error(std::string("frame ring teardown: ") + error.what());
  }
  for (Slot& slot : slots_) vkDestroyCommandPool(device_.vk(), slot.pool, nullptr);
}

void FrameRing::retire(Slot& slot) {
  if (!slot.pending) return;
  device_.waitFor(slot.retireValue);
  if (!device_.lost()) lastTimings_ = slot.timer->resolve();  // a lost device wrote none
  lastRetiredFrame_ = slot.frameIndex;
  slot.pending = false;
}

FrameRing::Frame& FrameRing::begin() {
  require(!recording_, "FrameRing::begin", "previous frame was not submitted");
  const auto slotIndex = static_cast<std::uint32_t>(nextFrame_ % kFramesInFlight);
  Slot& slot = slots_[slotIndex];
  retire(slot);
  device_.collectGarbage();
  GFX_CHECK(vkResetCommandPool(device_.vk(), slot.pool, 0));
  slot.descriptors->reset();
  slot.timer->reset();
  slot.constants->reset();
  slot.frameIndex = nextFrame_;

  VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  GFX_CHECK(vkBeginCommandBuffer(slot.cmd, &beginInfo));
  recording_ = true;
  current_ = Frame{nextFrame_,       slotIndex,           slot.cmd, slot.descriptors.get(),
                   slot.timer.get(), slot.constants.get()};
  ++nextFrame_;
  return current_;
}

std::uint64_t FrameRing::submit(std::span<const VkSemaphoreSubmitInfo> waits,
                                std::span<const VkSemaphoreSubmitInfo> signals) {
  require(recording_, "FrameRing::submit", "no frame is being recorded");
  Slot& slot = slots_[current_.slot];
  GFX_CHECK(vkEndCommandBuffer(slot.cmd));
  slot.retireValue = device_.submit(std::span<const VkCommandBuffer>(&slot.cmd, 1), waits, signals);
  slot.pending = true;
  recording_ = false;
  return slot.retireValue;
}

void FrameRing::drain() {
  // Retire in submission order so lastTimings() ends up describing the newest frame.
  for (std::uint64_t i = 0; i < kFramesInFlight; ++i) {
    retire(slots_[(nextFrame_ + i) % kFramesInFlight]);
  }
  device_.collectGarbage();
}

}  // namespace engine::gfx
