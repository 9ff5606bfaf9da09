#include "vkfx/pass_timer.h"

namespace vkfx {

PassTimer::PassTimer(const DeviceContext& device, std::uint32_t slots,
                     std::span<const char* const> names)
    : device_(device),
      names_(names),
      passes_(static_cast<std::uint32_t>(names.size())),
      recorded_(slots) {
  VkPhysicalDeviceProperties properties{};
  device.fn().vkGetPhysicalDeviceProperties(device.physicalDevice(), &properties);
  if (properties.limits.timestampComputeAndGraphics == VK_FALSE ||
      properties.limits.timestampPeriod <= 0.0f) {
    return;
  }
  nanosecondsPerTick_ = properties.limits.timestampPeriod;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = slots * passes_ * 2;
  pool_ = device.createQueryPool(info, "pass timestamps");
}

void PassTimer::beginFrame(VkCommandBuffer cmd, std::uint32_t slot) {
  slot_ = slot;
  recorded_[slot].clear();
  if (!pool_) return;
  device_.fn().vkCmdResetQueryPool(cmd, pool_.get(), query(slot, 0, 0), passes_ * 2);
}

void PassTimer::begin(VkCommandBuffer cmd, std::uint32_t pass) {
  if (!pool_) return;
  stamp(cmd, query(slot_, pass, 0));
}

void PassTimer::end(VkCommandBuffer cmd, std::uint32_t pass) {
  if (!pool_) return;
  stamp(cmd, query(slot_, pass, 1));
  recorded_[slot_].push_back(pass);
}

void PassTimer::stamp(VkCommandBuffer cmd, std::uint32_t queryIndex) {
  // Everything recorded so far completes, then the timestamp is taken and, through the second
  // dependency, realised at once: lavapipe writes a timestamp only when it next synchronises,
  // which without it would be after the following pass's dispatch.
  executionBarrier(cmd);
  device_.fn().vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_.get(),
                                    queryIndex);
  executionBarrier(cmd);
}

void PassTimer::executionBarrier(VkCommandBuffer cmd) const {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.memoryBarrierCount = 1;
  dependency.pMemoryBarriers = &barrier;
  device_.fn().vkCmdPipelineBarrier2(cmd, &dependency);
}

std::vector<PassTime> PassTimer::read(std::uint32_t slot) const {
  std::vector<PassTime> timings;
  if (!pool_) return timings;
  for (std::uint32_t pass : recorded_[slot]) {
    std::uint64_t ticks[2] = {0, 0};
    const VkResult result = device_.fn().vkGetQueryPoolResults(
        device_.device(), pool_.get(), query(slot, pass, 0), 2, sizeof(ticks), ticks,
        sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT);
    if (result != VK_SUCCESS) return {};  // not complete: the caller asked too early
    timings.push_back(
        PassTime{names_[pass], double(ticks[1] - ticks[0]) * nanosecondsPerTick_ * 1e-6});
  }
  return timings;
}

}  // namespace vkfx
