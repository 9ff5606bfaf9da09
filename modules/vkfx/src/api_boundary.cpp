#include "vkfx/api_boundary.h"

#include <cmath>

namespace vkfx {

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finitePosition(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool nonNegative(const glm::vec3& v) {
  return v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f;
}

std::string extentText(VkExtent2D e) {
  return std::to_string(e.width) + "x" + std::to_string(e.height);
}

std::string checkExtentWithin(const char* field, VkExtent2D extent, VkExtent2D maxRenderExtent) {
  if (extent.width == 0 || extent.height == 0 || extent.width > maxRenderExtent.width ||
      extent.height > maxRenderExtent.height) {
    return std::string(field) + " = " + extentText(extent) +
           ": must be non-zero and within CreateInfo.maxRenderExtent (" +
           extentText(maxRenderExtent) + ")";
  }
  return {};
}

std::string checkDeviceAndLimits(VkInstance instance, VkPhysicalDevice physicalDevice,
                                 VkDevice device, PFN_vkGetInstanceProcAddr getInstanceProcAddr,
                                 PFN_vkGetDeviceProcAddr getDeviceProcAddr,
                                 std::uint32_t maxFramesInFlight, VkExtent2D maxRenderExtent) {
  if (device == VK_NULL_HANDLE || physicalDevice == VK_NULL_HANDLE || instance == VK_NULL_HANDLE ||
      getDeviceProcAddr == nullptr || getInstanceProcAddr == nullptr) {
    return "CreateInfo: instance, physicalDevice, device and both proc-addr functions are "
           "required";
  }
  if (maxFramesInFlight < 1 || maxFramesInFlight > 8) {
    return "CreateInfo.maxFramesInFlight = " + std::to_string(maxFramesInFlight) +
           ": must be in [1, 8]";
  }
  if (maxRenderExtent.width == 0 || maxRenderExtent.height == 0 || maxRenderExtent.width > 16384 ||
      maxRenderExtent.height > 16384) {
    return "CreateInfo.maxRenderExtent = " + extentText(maxRenderExtent) +
           ": must be in [1, 16384] per side";
  }
  return {};
}

}  // namespace vkfx
