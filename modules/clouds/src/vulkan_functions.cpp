#include "vulkan_functions.h"

namespace clouds::detail {

bool VulkanFunctions::load(const CreateInfo& info, std::string* missing) {
  auto fail = [&](const char* name) {
    if (missing != nullptr) *missing = name;
    return false;
  };
#define CLOUDS_LOAD_INSTANCE(name)                                                     \
  name = reinterpret_cast<PFN_##name>(info.getInstanceProcAddr(info.instance, #name)); \
  if (name == nullptr) return fail(#name);
#define CLOUDS_LOAD_DEVICE(name)                                                   \
  name = reinterpret_cast<PFN_##name>(info.getDeviceProcAddr(info.device, #name)); \
  if (name == nullptr) return fail(#name);
#define CLOUDS_LOAD_OPTIONAL(name) \
  name = reinterpret_cast<PFN_##name>(info.getDeviceProcAddr(info.device, #name));
  CLOUDS_INSTANCE_FUNCTIONS(CLOUDS_LOAD_INSTANCE)
  CLOUDS_DEVICE_FUNCTIONS(CLOUDS_LOAD_DEVICE)
  if (info.debugUtils) {
    CLOUDS_OPTIONAL_DEVICE_FUNCTIONS(CLOUDS_LOAD_OPTIONAL)
  }
#undef CLOUDS_LOAD_INSTANCE
#undef CLOUDS_LOAD_DEVICE
#undef CLOUDS_LOAD_OPTIONAL
  return true;
}

}  // namespace clouds::detail
