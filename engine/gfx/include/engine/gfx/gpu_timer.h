#pragma once
// GPU timestamps around named scopes in one command buffer. One timer per frame slot: write
// scopes while recording, resolve them after the submission has completed.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

#include "engine/gfx/device.h"

namespace engine::gfx {

struct TimedScope {
  const char* name = "";  // static or owned by the caller for the timer's lifetime
  double milliseconds = 0.0;
};

class GpuTimer {
 public:
  GpuTimer(Device& device, std::uint32_t maxScopes, const char* debugName);
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  // Host-resets the queries; only when the previous use of this timer has completed.
  void reset();
  // Returns a scope id, or UINT32_MAX when all scopes are used (the scope is then not timed).
  std::uint32_t begin(VkCommandBuffer cmd, const char* name);
  void end(VkCommandBuffer cmd, std::uint32_t scope);
  // Reads the timestamps written since reset(); the submission must have completed.
  std::span<const TimedScope> resolve();
  std::span<const TimedScope> lastResolved() const { return {resolved_.data(), resolvedCount_}; }

 private:
  Device& device_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  std::uint32_t maxScopes_;
  std::uint32_t used_ = 0;
  std::vector<const char*> names_;
  std::vector<std::uint64_t> raw_;
  std::vector<TimedScope> resolved_;
  std::size_t resolvedCount_ = 0;
  double nanosecondsPerTick_;
  std::uint64_t validMask_;
};

}  // namespace engine::gfx
