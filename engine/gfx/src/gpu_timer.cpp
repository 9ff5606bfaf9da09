#include "engine/gfx/gpu_timer.h"

#include "engine/gfx/vk_check.h"

namespace engine::gfx {

GpuTimer::GpuTimer(Device& device, std::uint32_t maxScopes, const char* debugName)
    : device_(device),
      maxScopes_(maxScopes),
      names_(maxScopes, ""),
      raw_(std::size_t{2} * maxScopes, 0),
      resolved_(maxScopes),
      nanosecondsPerTick_(static_cast<double>(device.properties().limits.timestampPeriod)) {
  std::uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &familyCount, families.data());
  const std::uint32_t bits = families[device.queueFamily()].timestampValidBits;
  validMask_ = bits >= 64 ? ~std::uint64_t{0} : ((std::uint64_t{1} << bits) - 1);

  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2 * maxScopes;
  GFX_CHECK(vkCreateQueryPool(device.vk(), &info, nullptr, &pool_));
  setName(device, pool_, debugName);
  vkResetQueryPool(device.vk(), pool_, 0, 2 * maxScopes);
}

GpuTimer::~GpuTimer() {
  device_.release(VK_OBJECT_TYPE_QUERY_POOL, handleBits(pool_));
}

void GpuTimer::reset() {
  if (used_ > 0) vkResetQueryPool(device_.vk(), pool_, 0, 2 * used_);
  used_ = 0;
}

std::uint32_t GpuTimer::begin(VkCommandBuffer cmd, const char* name) {
  if (used_ == maxScopes_) return UINT32_MAX;
  const std::uint32_t scope = used_++;
  names_[scope] = name;
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * scope);
  return scope;
}

void GpuTimer::end(VkCommandBuffer cmd, std::uint32_t scope) {
  if (scope == UINT32_MAX) return;
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * scope + 1);
}

std::span<const TimedScope> GpuTimer::resolve() {
  resolvedCount_ = 0;
  if (used_ == 0) return {};
  GFX_CHECK(vkGetQueryPoolResults(
      device_.vk(), pool_, 0, 2 * used_, sizeof(std::uint64_t) * 2 * used_, raw_.data(),
      sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  for (std::uint32_t i = 0; i < used_; ++i) {
    const std::uint64_t start = raw_[2 * i] & validMask_;
    const std::uint64_t stop = raw_[2 * i + 1] & validMask_;
    const std::uint64_t ticks = stop >= start ? stop - start : 0;
    resolved_[i] = TimedScope{names_[i], static_cast<double>(ticks) * nanosecondsPerTick_ * 1e-6};
  }
  resolvedCount_ = used_;
  return {resolved_.data(), resolvedCount_};
}

}  // namespace engine::gfx
