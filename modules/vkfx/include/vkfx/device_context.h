#pragma once
// An effect module's view of the host device: the function table, memory types, debug names
// and labels (only when the host enabled VK_EXT_debug_utils), and the creation of every Vulkan
// object the module owns. Each create* returns the object already wrapped in its owner
// (vk_handle.h), so nothing the module creates is ever held by a raw handle, and a failure is
// a vkfx::Error the module's API boundary turns into its own error code.
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

#include "vkfx/vk_handle.h"
#include "vkfx/vulkan_functions.h"

namespace vkfx {

// What kind of failure an Error is; modules map it to their public error codes.
enum class Failure : std::uint32_t {
  OutOfMemory,    // host, device or descriptor-pool memory
  VulkanFailure,  // any other Vulkan error
  Unsupported,    // the device lacks something the module needs
};

// Thrown inside a module on failures and caught at its public API boundary, which reports it
// through its error out-parameter (module APIs do not throw).
class Error : public std::runtime_error {
 public:
  Error(Failure failure, const std::string& message)
      : std::runtime_error(message), failure_(failure) {}
  Failure failure() const { return failure_; }

 private:
  Failure failure_;
};

// Throws an Error naming `what` unless `result` is VK_SUCCESS (OutOfMemory for the
// out-of-memory results of host, device or descriptor pool, VulkanFailure otherwise).
void check(VkResult result, const char* what);

template <typename Handle>
std::uint64_t bits(Handle handle) {
  return reinterpret_cast<std::uint64_t>(handle);
}

class DeviceContext {
 public:
  // `prefix` starts every debug name and error message ("clouds", "atmosphere").
  DeviceContext(VkDevice device, VkPhysicalDevice physical, bool debugUtils,
                const VulkanFunctions& functions, std::string prefix);

  const VulkanFunctions& fn() const { return fn_; }
  VkDevice device() const { return device_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  const std::string& prefix() const { return prefix_; }
  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags wanted) const;
  bool supportsStorage(VkFormat format) const;

  // Debug names and labels: no-ops unless CreateInfo::debugUtils.
  void name(VkObjectType type, std::uint64_t handle, const std::string& name) const;
  void beginLabel(VkCommandBuffer cmd, const char* name) const;
  void endLabel(VkCommandBuffer cmd) const;

  UniqueImage createImage(const VkImageCreateInfo& info, const std::string& name) const;
  UniqueImageView createImageView(const VkImageViewCreateInfo& info, const std::string& name) const;
  UniqueBuffer createBuffer(const VkBufferCreateInfo& info, const std::string& name) const;
  UniqueMemory allocateMemory(const VkMemoryAllocateInfo& info, const std::string& name) const;
  // Memory for `requirements`, of a type with `preferred` properties when one exists.
  UniqueMemory allocateFor(const VkMemoryRequirements& requirements,
                           VkMemoryPropertyFlags preferred, const std::string& name) const;
  UniqueSampler createSampler(const VkSamplerCreateInfo& info, const std::string& name) const;
  // A sampler without mipmaps, clamped to the edges in v and w and `addressU` in u (REPEAT for
  // maps that wrap around in azimuth or tile).
  UniqueSampler createSampler(VkFilter filter, VkSamplerAddressMode addressU,
                              const std::string& name) const;
  UniqueShaderModule createShaderModule(const VkShaderModuleCreateInfo& info,
                                        const std::string& name) const;
  UniqueSetLayout createSetLayout(const VkDescriptorSetLayoutCreateInfo& info,
                                  const std::string& name) const;
  UniquePipelineLayout createPipelineLayout(const VkPipelineLayoutCreateInfo& info,
                                            const std::string& name) const;
  UniquePipeline createGraphicsPipeline(const VkGraphicsPipelineCreateInfo& info,
                                        const std::string& name) const;
  UniquePipeline createComputePipeline(const VkComputePipelineCreateInfo& info,
                                       const std::string& name) const;
  UniqueDescriptorPool createDescriptorPool(const VkDescriptorPoolCreateInfo& info,
                                            const std::string& name) const;
  UniqueQueryPool createQueryPool(const VkQueryPoolCreateInfo& info, const std::string& name) const;

 private:
  template <typename Unique, auto Create, typename Info>
  Unique make(const Info& info, VkObjectType type, const char* what, const std::string& name) const;
  // One pipeline through vkCreate{Graphics,Compute}Pipelines (no cache).
  template <auto Create, typename Info>
  UniquePipeline makePipeline(const Info& info, const char* what, const std::string& name) const;

  VulkanFunctions fn_;
  VkDevice device_;
  VkPhysicalDevice physical_;
  bool debugUtils_;
  std::string prefix_;
  VkPhysicalDeviceMemoryProperties memory_{};
};

// The stages and accesses the module's compute passes synchronise on.
inline constexpr VkPipelineStageFlags2 kComputeStage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
inline constexpr VkAccessFlags2 kStorageWrite = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
inline constexpr VkAccessFlags2 kStorageRead = VK_ACCESS_2_SHADER_STORAGE_READ_BIT;

// Workgroups to cover `size` items with groups of `group`.
constexpr std::uint32_t groupsFor(std::uint32_t size, std::uint32_t group) {
  return (size + group - 1) / group;
}

// One image barrier in GENERAL layout or a transition, for compute-only module work.
void barrier(const DeviceContext& context, VkCommandBuffer cmd, VkImage image,
             VkImageLayout oldLayout, VkImageLayout newLayout, VkPipelineStageFlags2 srcStages,
             VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);
void memoryBarrier(const DeviceContext& context, VkCommandBuffer cmd,
                   VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);

}  // namespace vkfx
