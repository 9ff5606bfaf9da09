#include "engine/gfx/vk_check.h"

#include <string>

namespace engine::gfx {

const char* resultName(VkResult result) {
  switch (result) {
#define GFX_RESULT_CASE(r) \
  case r:                  \
    return #r;
    GFX_RESULT_CASE(VK_SUCCESS)
    GFX_RESULT_CASE(VK_NOT_READY)
    GFX_RESULT_CASE(VK_TIMEOUT)
    GFX_RESULT_CASE(VK_INCOMPLETE)
    GFX_RESULT_CASE(VK_SUBOPTIMAL_KHR)
    GFX_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    GFX_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    GFX_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    GFX_RESULT_CASE(VK_ERROR_DEVICE_LOST)
    GFX_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    GFX_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    GFX_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    GFX_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    GFX_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    GFX_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    GFX_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    GFX_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
    GFX_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    GFX_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR)
    GFX_RESULT_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    GFX_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR)
#undef GFX_RESULT_CASE
    default:
      return "VkResult(unknown)";
  }
}

void throwVulkanError(VkResult result, const char* expression, const char* file, int line) {
  throw VulkanError(std::string(expression) + " failed with " + resultName(result) + " at " + file +
                        ":" + std::to_string(line),
                    result);
}

}  // namespace engine::gfx
