#pragma once
// Which physical device to use. Pure logic, unit-tested: real GPUs beat lavapipe, and the
// CLOUDSCAPE_DEVICE environment variable can force "cpu", "gpu" or a name substring.
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace engine::gfx {

struct DeviceCandidate {
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  bool suitable = false;  // Vulkan 1.3, required features, a graphics+compute(+present) queue
  std::string unsuitableReason;
};

// Returns the index of the chosen candidate, or throws engine::Error explaining why none fits.
// `preference`: empty (best real GPU, else CPU), "cpu", "gpu", or a case-insensitive substring
// of the device name.
std::size_t chooseDevice(const std::vector<DeviceCandidate>& candidates,
                         const std::string& preference);

// The value of CLOUDSCAPE_DEVICE, or empty.
std::string devicePreferenceFromEnvironment();

}  // namespace engine::gfx
