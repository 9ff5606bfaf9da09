#include "vkfx/vulkan_functions.h"

namespace vkfx {

bool VulkanFunctions::load(VkInstance instance, VkDevice device,
                           PFN_vkGetInstanceProcAddr getInstanceProcAddr,
                           PFN_vkGetDeviceProcAddr getDeviceProcAddr, bool debugUtils,
                           std::string* missing) {
  auto fail = [&](const char* name) {
    if (missing != nullptr) *missing = name;
    return false;
  };
#define VKFX_LOAD_INSTANCE(name)                                             \
  name = reinterpret_cast<PFN_##name>(getInstanceProcAddr(instance, #name)); \
  if (name == nullptr) return fail(#name);
#define VKFX_LOAD_DEVICE(name)                                           \
  name = reinterpret_cast<PFN_##name>(getDeviceProcAddr(device, #name)); \
  if (name == nullptr) return fail(#name);
#define VKFX_LOAD_OPTIONAL(name) \
  name = reinterpret_cast<PFN_##name>(getDeviceProcAddr(device, #name));
  VKFX_INSTANCE_FUNCTIONS(VKFX_LOAD_INSTANCE)
  VKFX_DEVICE_FUNCTIONS(VKFX_LOAD_DEVICE)
  if (debugUtils) {
    VKFX_OPTIONAL_DEVICE_FUNCTIONS(VKFX_LOAD_OPTIONAL)
  }
#undef VKFX_LOAD_INSTANCE
#undef VKFX_LOAD_DEVICE
#undef VKFX_LOAD_OPTIONAL
  return true;
}

}  // namespace vkfx
