#pragma once
// The Vulkan entry points an effect module uses, loaded through the host's vkGet*ProcAddr so
// the module never links the loader and works with any host setup (static linking, volk, a
// shim that counts or fails calls in tests).
#include <vulkan/vulkan.h>

#include <string>

namespace vkfx {

#define VKFX_INSTANCE_FUNCTIONS(X)       \
  X(vkGetPhysicalDeviceMemoryProperties) \
  X(vkGetPhysicalDeviceProperties)       \
  X(vkGetPhysicalDeviceFormatProperties)

#define VKFX_DEVICE_FUNCTIONS(X)   \
  X(vkCreateImage)                 \
  X(vkDestroyImage)                \
  X(vkGetImageMemoryRequirements)  \
  X(vkBindImageMemory)             \
  X(vkCreateImageView)             \
  X(vkDestroyImageView)            \
  X(vkCreateBuffer)                \
  X(vkDestroyBuffer)               \
  X(vkGetBufferMemoryRequirements) \
  X(vkBindBufferMemory)            \
  X(vkAllocateMemory)              \
  X(vkFreeMemory)                  \
  X(vkCreateSampler)               \
  X(vkDestroySampler)              \
  X(vkCreateShaderModule)          \
  X(vkDestroyShaderModule)         \
  X(vkCreateDescriptorSetLayout)   \
  X(vkDestroyDescriptorSetLayout)  \
  X(vkCreatePipelineLayout)        \
  X(vkDestroyPipelineLayout)       \
  X(vkCreateComputePipelines)      \
  X(vkCreateGraphicsPipelines)     \
  X(vkDestroyPipeline)             \
  X(vkCreateDescriptorPool)        \
  X(vkDestroyDescriptorPool)       \
  X(vkAllocateDescriptorSets)      \
  X(vkUpdateDescriptorSets)        \
  X(vkCmdBindPipeline)             \
  X(vkCmdBindDescriptorSets)       \
  X(vkCmdPushConstants)            \
  X(vkCmdDispatch)                 \
  X(vkCmdDispatchIndirect)         \
  X(vkCmdDraw)                     \
  X(vkCmdSetViewport)              \
  X(vkCmdSetScissor)               \
  X(vkCmdPipelineBarrier2)         \
  X(vkCmdUpdateBuffer)             \
  X(vkCmdFillBuffer)               \
  X(vkCmdClearColorImage)          \
  X(vkCmdCopyImage)                \
  X(vkCmdCopyBufferToImage)        \
  X(vkMapMemory)                   \
  X(vkCreateQueryPool)             \
  X(vkDestroyQueryPool)            \
  X(vkCmdResetQueryPool)           \
  X(vkCmdWriteTimestamp2)          \
  X(vkGetQueryPoolResults)

// Loaded only when the host says it enabled VK_EXT_debug_utils: loaders return these entry
// points whether or not the extension is enabled, and calling them when it is not is a
// validation error. Null otherwise (names and labels are then skipped).
#define VKFX_OPTIONAL_DEVICE_FUNCTIONS(X) \
  X(vkSetDebugUtilsObjectNameEXT)         \
  X(vkCmdBeginDebugUtilsLabelEXT)         \
  X(vkCmdEndDebugUtilsLabelEXT)

struct VulkanFunctions {
#define VKFX_DECLARE(name) PFN_##name name = nullptr;
  VKFX_INSTANCE_FUNCTIONS(VKFX_DECLARE)
  VKFX_DEVICE_FUNCTIONS(VKFX_DECLARE)
  VKFX_OPTIONAL_DEVICE_FUNCTIONS(VKFX_DECLARE)
#undef VKFX_DECLARE

  // Returns false and fills `missing` with the first required function the host's proc-addr
  // functions do not provide. `debugUtils`: the host enabled VK_EXT_debug_utils.
  bool load(VkInstance instance, VkDevice device, PFN_vkGetInstanceProcAddr getInstanceProcAddr,
            PFN_vkGetDeviceProcAddr getDeviceProcAddr, bool debugUtils, std::string* missing);
};

}  // namespace vkfx
