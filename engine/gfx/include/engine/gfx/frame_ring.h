#pragma once
// Frames in flight. Each slot owns a command pool and buffer, a descriptor arena, a GPU timer
// and a ring of host-visible memory for per-frame constants. begin() waits until the slot's
// previous submission has retired, then recycles all of it; nothing is heap-allocated per
// frame once warm.
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>

#include "engine/gfx/descriptors.h"
#include "engine/gfx/device.h"
#include "engine/gfx/gpu_timer.h"
#include "engine/gfx/resources.h"

namespace engine::gfx {

// A bump allocator over one persistently mapped buffer, reset each time its slot is reused.
class ConstantRing {
 public:
  ConstantRing(Device& device, VkDeviceSize capacityBytes, const std::string& debugName);

  struct Slice {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
    std::byte* data = nullptr;
  };
  // Throws engine::Error when the ring is exhausted (raise the capacity).
  Slice allocate(VkDeviceSize bytes);
  template <typename T>
  Slice push(const T& value) {
    Slice slice = allocate(sizeof(T));
    std::memcpy(slice.data, &value, sizeof(T));
    return slice;
  }
  void reset() { head_ = 0; }

 private:
  Buffer buffer_;
  VkDeviceSize alignment_;
  VkDeviceSize head_ = 0;
};

class FrameRing {
 public:
  static constexpr std::uint32_t kFramesInFlight = 2;
  static constexpr std::uint32_t kMaxTimedScopes = 64;

  struct Frame {
    std::uint64_t index = 0;  // frames begun since creation, starting at 0
    std::uint32_t slot = 0;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    DescriptorArena* descriptors = nullptr;
    GpuTimer* timer = nullptr;
    ConstantRing* constants = nullptr;
  };

  explicit FrameRing(Device& device);
  ~FrameRing();
  FrameRing(const FrameRing&) = delete;
  FrameRing& operator=(const FrameRing&) = delete;

  // Waits for the slot's previous use, resolves its timings, recycles it and begins recording.
  Frame& begin();
  // Ends recording and submits; returns the timeline value that marks this frame's retirement.
  std::uint64_t submit(std::span<const VkSemaphoreSubmitInfo> waits = {},
                       std::span<const VkSemaphoreSubmitInfo> signals = {});
  // Waits until every submitted frame has retired.
  void drain();

  // GPU scopes of the most recently retired frame (empty until one has retired).
  std::span<const TimedScope> lastTimings() const { return lastTimings_; }
  std::uint64_t lastRetiredFrameIndex() const { return lastRetiredFrame_; }
  // Frames begun so far: the next frame's index.
  std::uint64_t framesBegun() const { return nextFrame_; }
  Device& device() { return device_; }

 private:
  void createSlots();
  struct Slot {
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    std::unique_ptr<DescriptorArena> descriptors;
    std::unique_ptr<GpuTimer> timer;
    std::unique_ptr<ConstantRing> constants;
    std::uint64_t retireValue = 0;
    std::uint64_t frameIndex = 0;
    bool pending = false;
  };
  void retire(Slot& slot);

  Device& device_;
  std::array<Slot, kFramesInFlight> slots_;
  Frame current_;
  std::uint64_t nextFrame_ = 0;
  bool recording_ = false;
  std::span<const TimedScope> lastTimings_;
  std::uint64_t lastRetiredFrame_ = 0;
};

}  // namespace engine::gfx
