#pragma once
// Optional GPU timestamps around each of the module's passes (CreateInfo::passTimings), so a
// host or benchmark can see where a frame's time goes. One query range per frame slot, reset
// at the start of the slot's frame and read back once the host knows the frame completed.
// Each timestamp sits between full execution barriers, so a pass's time is its own work on
// any device (the price: passes cannot overlap while timed).
#include <array>
#include <cstdint>
#include <vector>

#include "clouds/clouds.h"
#include "device_context.h"

namespace clouds::detail {

enum class Pass : std::uint32_t {
  Noise,
  Weather,
  SkyAmbient,
  ClearSky,
  SceneDistance,
  March,
  Reconstruct,
  Upsample,
  Count
};

class PassTimer {
 public:
  // Disabled (every call a no-op, read() empty) when the device has no compute timestamps.
  PassTimer(const DeviceContext& device, std::uint32_t slots);
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

  void beginFrame(VkCommandBuffer cmd, std::uint32_t slot);
  void begin(VkCommandBuffer cmd, Pass pass);
  void end(VkCommandBuffer cmd, Pass pass);
  // The passes recorded in `slot`'s last frame, in recording order; empty if not available.
  std::vector<PassTiming> read(std::uint32_t slot) const;

 private:
  static constexpr auto kPasses = static_cast<std::uint32_t>(Pass::Count);
  void stamp(VkCommandBuffer cmd, std::uint32_t queryIndex);
  void executionBarrier(VkCommandBuffer cmd) const;
  std::uint32_t query(std::uint32_t slot, Pass pass, std::uint32_t which) const {
    return (slot * kPasses + static_cast<std::uint32_t>(pass)) * 2 + which;
  }

  const DeviceContext& device_;
  UniqueQueryPool pool_;
  double nanosecondsPerTick_ = 0.0;
  std::uint32_t slot_ = 0;
  // Per slot: the passes recorded in its last frame, in order.
  std::vector<std::vector<Pass>> recorded_;
};

}  // namespace clouds::detail
