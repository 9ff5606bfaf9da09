#include "vulkan_shim.h"

#include <cstring>

namespace test::shim {
namespace {

Counts gCounts;
int gFailAt = 0;  // creation number that fails, counted from when it was armed
int gSinceArmed = 0;
bool gFailed = false;

template <typename Handle>
std::uint64_t bits(Handle h) {
  return reinterpret_cast<std::uint64_t>(h);
}

// True when this creation must fail.
bool failNow() {
  ++gCounts.creations;
  if (gFailAt == 0) return false;
  if (++gSinceArmed != gFailAt) return false;
  gFailed = true;
  return true;
}

// --- Creation and destruction of the common shape ------------------------------------------
template <typename Pfn>
struct Real {
  static inline Pfn fn = nullptr;
};

template <typename Pfn, const char* Name, typename Info, typename Handle>
VKAPI_ATTR VkResult VKAPI_CALL create(VkDevice device, const Info* info,
                                      const VkAllocationCallbacks* allocator, Handle* out) {
  if (failNow()) return VK_ERROR_OUT_OF_DEVICE_MEMORY;
  const VkResult result = Real<Pfn>::fn(device, info, allocator, out);
  if (result == VK_SUCCESS) gCounts.live[bits(*out)] = Name;
  return result;
}

template <typename Pfn, typename Handle>
VKAPI_ATTR void VKAPI_CALL destroy(VkDevice device, Handle handle,
                                   const VkAllocationCallbacks* allocator) {
  if (handle != VK_NULL_HANDLE) gCounts.live.erase(bits(handle));
  Real<Pfn>::fn(device, handle, allocator);
}

// vkCreateComputePipelines and vkCreateGraphicsPipelines: one creation per call.
template <typename Info, const char* Name>
struct CreatePipelines {
  using Pfn = VkResult(VKAPI_PTR*)(VkDevice, VkPipelineCache, std::uint32_t, const Info*,
                                   const VkAllocationCallbacks*, VkPipeline*);
  static inline Pfn real = nullptr;
  static VKAPI_ATTR VkResult VKAPI_CALL call(VkDevice device, VkPipelineCache cache,
                                             std::uint32_t count, const Info* infos,
                                             const VkAllocationCallbacks* allocator,
                                             VkPipeline* out) {
    if (failNow()) return VK_ERROR_OUT_OF_DEVICE_MEMORY;
    const VkResult result = real(device, cache, count, infos, allocator, out);
    if (result == VK_SUCCESS) {
      for (std::uint32_t i = 0; i < count; ++i) gCounts.live[bits(out[i])] = Name;
    }
    return result;
  }
};
constexpr char kComputePipelines[] = "vkCreateComputePipelines";
constexpr char kGraphicsPipelines[] = "vkCreateGraphicsPipelines";
using ComputePipelines = CreatePipelines<VkComputePipelineCreateInfo, kComputePipelines>;
using GraphicsPipelines = CreatePipelines<VkGraphicsPipelineCreateInfo, kGraphicsPipelines>;

PFN_vkAllocateDescriptorSets realAllocateSets = nullptr;
VKAPI_ATTR VkResult VKAPI_CALL allocateSets(VkDevice device,
                                            const VkDescriptorSetAllocateInfo* info,
                                            VkDescriptorSet* out) {
  if (failNow()) return VK_ERROR_OUT_OF_POOL_MEMORY;
  return realAllocateSets(device, info, out);
}

// --- Commands: counted and passed through ----------------------------------------------------
template <typename Pfn>
struct Command;
template <typename R, typename... Args>
struct Command<R(VKAPI_PTR*)(Args...)> {
  static inline R(VKAPI_PTR* real)(Args...) = nullptr;
  static VKAPI_ATTR R VKAPI_CALL call(Args... args) {
    ++gCounts.commands;
    return real(args...);
  }
};

#define SHIM_NAME(name) constexpr char k_##name[] = #name;
SHIM_NAME(vkCreateImage)
SHIM_NAME(vkCreateImageView)
SHIM_NAME(vkCreateBuffer)
SHIM_NAME(vkAllocateMemory)
SHIM_NAME(vkCreateSampler)
SHIM_NAME(vkCreateShaderModule)
SHIM_NAME(vkCreateDescriptorSetLayout)
SHIM_NAME(vkCreatePipelineLayout)
SHIM_NAME(vkCreateDescriptorPool)
SHIM_NAME(vkCreateQueryPool)
#undef SHIM_NAME

struct Entry {
  const char* name;
  PFN_vkVoidFunction shim;
  PFN_vkVoidFunction* real;
};

#define SHIM_CREATE(name, Info, Handle)                                                          \
  Entry {                                                                                        \
#name, reinterpret_cast < PFN_vkVoidFunction>(&create <PFN_##name, k_##name, Info, Handle>), \
        reinterpret_cast < PFN_vkVoidFunction*>(&Real <PFN_##name>::fn)                          \
  }
#define SHIM_DESTROY(name, Handle)                                                \
  Entry {                                                                         \
#name, reinterpret_cast < PFN_vkVoidFunction>(&destroy <PFN_##name, Handle>), \
        reinterpret_cast < PFN_vkVoidFunction*>(&Real <PFN_##name>::fn)           \
  }
#define SHIM_COMMAND(name)                                                      \
  Entry {                                                                       \
#name, reinterpret_cast < PFN_vkVoidFunction>(&Command <PFN_##name>::call), \
        reinterpret_cast < PFN_vkVoidFunction*>(&Command <PFN_##name>::real)    \
  }

const Entry kEntries[] = {
    SHIM_CREATE(vkCreateImage, VkImageCreateInfo, VkImage),
    SHIM_CREATE(vkCreateImageView, VkImageViewCreateInfo, VkImageView),
    SHIM_CREATE(vkCreateBuffer, VkBufferCreateInfo, VkBuffer),
    SHIM_CREATE(vkAllocateMemory, VkMemoryAllocateInfo, VkDeviceMemory),
    SHIM_CREATE(vkCreateSampler, VkSamplerCreateInfo, VkSampler),
    SHIM_CREATE(vkCreateShaderModule, VkShaderModuleCreateInfo, VkShaderModule),
    SHIM_CREATE(vkCreateDescriptorSetLayout, VkDescriptorSetLayoutCreateInfo,
                VkDescriptorSetLayout),
    SHIM_CREATE(vkCreatePipelineLayout, VkPipelineLayoutCreateInfo, VkPipelineLayout),
    SHIM_CREATE(vkCreateDescriptorPool, VkDescriptorPoolCreateInfo, VkDescriptorPool),
    SHIM_CREATE(vkCreateQueryPool, VkQueryPoolCreateInfo, VkQueryPool),
    SHIM_DESTROY(vkDestroyImage, VkImage),
    SHIM_DESTROY(vkDestroyImageView, VkImageView),
    SHIM_DESTROY(vkDestroyBuffer, VkBuffer),
    SHIM_DESTROY(vkFreeMemory, VkDeviceMemory),
    SHIM_DESTROY(vkDestroySampler, VkSampler),
    SHIM_DESTROY(vkDestroyShaderModule, VkShaderModule),
    SHIM_DESTROY(vkDestroyDescriptorSetLayout, VkDescriptorSetLayout),
    SHIM_DESTROY(vkDestroyPipelineLayout, VkPipelineLayout),
    SHIM_DESTROY(vkDestroyPipeline, VkPipeline),
    SHIM_DESTROY(vkDestroyDescriptorPool, VkDescriptorPool),
    SHIM_DESTROY(vkDestroyQueryPool, VkQueryPool),
    Entry{kComputePipelines, reinterpret_cast<PFN_vkVoidFunction>(&ComputePipelines::call),
          reinterpret_cast<PFN_vkVoidFunction*>(&ComputePipelines::real)},
    Entry{kGraphicsPipelines, reinterpret_cast<PFN_vkVoidFunction>(&GraphicsPipelines::call),
          reinterpret_cast<PFN_vkVoidFunction*>(&GraphicsPipelines::real)},
    Entry{"vkAllocateDescriptorSets", reinterpret_cast<PFN_vkVoidFunction>(&allocateSets),
          reinterpret_cast<PFN_vkVoidFunction*>(&realAllocateSets)},
    SHIM_COMMAND(vkCmdBindPipeline),
    SHIM_COMMAND(vkCmdBindDescriptorSets),
    SHIM_COMMAND(vkCmdPushConstants),
    SHIM_COMMAND(vkCmdDispatch),
    SHIM_COMMAND(vkCmdDraw),
    SHIM_COMMAND(vkCmdSetViewport),
    SHIM_COMMAND(vkCmdSetScissor),
    SHIM_COMMAND(vkCmdPipelineBarrier2),
    SHIM_COMMAND(vkCmdUpdateBuffer),
    SHIM_COMMAND(vkCmdFillBuffer),
    SHIM_COMMAND(vkCmdClearColorImage),
    SHIM_COMMAND(vkCmdCopyBufferToImage),
    SHIM_COMMAND(vkCmdResetQueryPool),
    SHIM_COMMAND(vkCmdWriteTimestamp2),
};

#undef SHIM_CREATE
#undef SHIM_DESTROY
#undef SHIM_COMMAND

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL shimGetDeviceProcAddr(VkDevice device, const char* name) {
  const PFN_vkVoidFunction real = vkGetDeviceProcAddr(device, name);
  for (const Entry& entry : kEntries) {
    if (std::strcmp(entry.name, name) == 0 && real != nullptr) {
      *entry.real = real;
      return entry.shim;
    }
  }
  return real;
}

}  // namespace

PFN_vkGetDeviceProcAddr getDeviceProcAddr() {
  return &shimGetDeviceProcAddr;
}
Counts& counts() {
  return gCounts;
}

void resetCounts() {
  gCounts.creations = 0;
  gCounts.commands = 0;
}

void failCreation(int n) {
  gFailAt = n;
  gSinceArmed = 0;
  gFailed = false;
}

bool failed() {
  return gFailed;
}

}  // namespace test::shim
