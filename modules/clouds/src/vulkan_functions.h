#pragma once
// The Vulkan entry points the module uses, loaded through the host's vkGet*ProcAddr so the
// module never links the loader and works with any host setup.
#include <vulkan/vulkan.h>

#include <string>

#include "clouds/clouds.h"

namespace clouds::detail {

#define CLOUDS_INSTANCE_FUNCTIONS(X)     \
  X(vkGetPhysicalDeviceMemoryProperties) \
  X(vkGetPhysicalDeviceProperties)       \
  X(vkGetPhysicalDeviceFormatProperties)

#define CLOUDS_DEVICE_FUNCTIONS(X) \
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
  X(vkDestroyPipeline)             \
  X(vkCreateDescriptorPool)        \
  X(vkDestroyDescriptorPool)       \
  X(vkAllocateDescriptorSets)      \
  X(vkUpdateDescriptorSets)        \
  X(vkCmdBindPipeline)             \
  X(vkCmdBindDescriptorSets)       \
  X(vkCmdPushConstants)            \
  X(vkCmdDispatch)                 \
  X(vkCmdPipelineBarrier2)         \
  X(vkCmdUpdateBuffer)             \
  X(vkCmdFillBuffer)               \
  X(vkCmdClearColorImage)          \
  X(vkMapMemory)                   \
  X(vkCreateQueryPool)             \
  X(vkDestroyQueryPool)            \
  X(vkCmdResetQueryPool)           \
  X(vkCmdWriteTimestamp2)          \
  X(vkGetQueryPoolResults)

// Loaded only when CreateInfo::debugUtils says the host enabled VK_EXT_debug_utils: loaders
// return these entry points whether or not the extension is enabled, and calling them when it
// is not is a validation error. Null otherwise (names and labels are then skipped).
#define CLOUDS_OPTIONAL_DEVICE_FUNCTIONS(X) \
  X(vkSetDebugUtilsObjectNameEXT)           \
  X(vkCmdBeginDebugUtilsLabelEXT)           \
  X(vkCmdEndDebugUtilsLabelEXT)

struct VulkanFunctions {
#define CLOUDS_DECLARE(name) PFN_##name name = nullptr;
  CLOUDS_INSTANCE_FUNCTIONS(CLOUDS_DECLARE)
  CLOUDS_DEVICE_FUNCTIONS(CLOUDS_DECLARE)
  CLOUDS_OPTIONAL_DEVICE_FUNCTIONS(CLOUDS_DECLARE)
#undef CLOUDS_DECLARE

  // Returns false and fills `missing` with the first required function the host's proc-addr
  // functions do not provide.
  bool load(const CreateInfo& info, std::string* missing);
};

}  // namespace clouds::detail
