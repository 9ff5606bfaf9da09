#pragma once
// Optional GPU timestamps around each of a module's passes, so a host or benchmark can see
// where a frame's time goes. Passes are numbered by the module (0 .. names.size() - 1). One
// query range per frame slot, reset at the start of the slot's frame and read back once the
// host knows the frame completed. Each timestamp sits between full execution barriers, so a
// pass's time is its own work on any device (the price: passes cannot overlap while timed).
#include <cstdint>
#include <span>
#include <vector>

#include "vkfx/device_context.h"

namespace vkfx {

struct PassTime {
  const char* name = "";  // one of the names given to the timer (static storage)
  double milliseconds = 0.0;
};

class PassTimer {
 public:
  // Disabled (every call a no-op, read() empty) when the device has no compute timestamps.
  // `names` must outlive the timer (string literals).
  PassTimer(const DeviceContext& device, std::uint32_t slots, std::span<const char* const> names);
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

  void beginFrame(VkCommandBuffer cmd, std::uint32_t slot);
  void begin(VkCommandBuffer cmd, std::uint32_t pass);
  void end(VkCommandBuffer cmd, std::uint32_t pass);
  // The passes recorded in `slot`'s last frame, in order; empty if not available yet.
  std::vector<PassTime> read(std::uint32_t slot) const;

 private:
  void stamp(VkCommandBuffer cmd, std::uint32_t queryIndex);
  void executionBarrier(VkCommandBuffer cmd) const;
  std::uint32_t query(std::uint32_t slot, std::uint32_t pass, std::uint32_t which) const {
    return (slot * passes_ + pass) * 2 + which;
  }

  const DeviceContext& device_;
  std::span<const char* const> names_;
  std::uint32_t passes_;
  UniqueQueryPool pool_;
  double nanosecondsPerTick_ = 0.0;
  std::uint32_t slot_ = 0;
  // Per slot: the passes recorded in its last frame, in order.
  std::vector<std::vector<std::uint32_t>> recorded_;
};

}  // namespace vkfx
