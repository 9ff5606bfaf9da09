#include "engine/gfx/device_selection.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "engine/core/error.h"

namespace engine::gfx {
namespace {

int typeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_OTHER:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 0;
    default:
      return 0;
  }
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string describe(const std::vector<DeviceCandidate>& candidates) {
  std::string text;
  for (const auto& c : candidates) {
    text += "\n  - " + c.name +
            (c.suitable ? " (suitable)" : " (unsuitable: " + c.unsuitableReason + ")");
  }
  return text.empty() ? "\n  (no Vulkan devices; install mesa-vulkan-drivers for lavapipe)" : text;
}

}  // namespace

std::size_t chooseDevice(const std::vector<DeviceCandidate>& candidates,
                         const std::string& preference) {
  const std::string wanted = lower(preference);
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const DeviceCandidate& c = candidates[i];
    if (!c.suitable) continue;
    const bool isCpu = c.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    if (wanted == "cpu" && !isCpu) continue;
    if (wanted == "gpu" && isCpu) continue;
    if (!wanted.empty() && wanted != "cpu" && wanted != "gpu" &&
        lower(c.name).find(wanted) == std::string::npos) {
      continue;
    }
    if (!best || typeRank(c.type) > typeRank(candidates[*best].type)) best = i;
  }
  if (!best) {
    throw Error("Vulkan device: none matches CLOUDSCAPE_DEVICE='" + preference +
                "'. Devices found:" + describe(candidates));
  }
  return *best;
}

std::string devicePreferenceFromEnvironment() {
  const char* value = std::getenv("CLOUDSCAPE_DEVICE");
  return value != nullptr ? std::string(value) : std::string();
}

}  // namespace engine::gfx
