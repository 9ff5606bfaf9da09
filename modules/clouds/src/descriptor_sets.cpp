#include "descriptor_sets.h"

#include <map>
#include <vector>

namespace clouds::detail {

UniqueDescriptorPool makeDescriptorPool(const DeviceContext& device, const Programs& programs,
                                        std::uint32_t frames) {
  std::map<VkDescriptorType, std::uint32_t> descriptors;
  std::uint32_t sets = 0;
  const auto add = [&](const SetsOf& entry, std::uint32_t times) {
    if (!programs.has(entry.program)) return;
    sets += entry.sets * times;
    for (const Binding& binding : programs[entry.program].bindings()) {
      descriptors[binding.type] += entry.sets * times;
    }
  };
  for (const SetsOf& entry : kFixedSets) add(entry, 1);
  for (const SetsOf& entry : kSlotSets) add(entry, frames);
  std::vector<VkDescriptorPoolSize> sizes;
  for (const auto& [type, count] : descriptors) sizes.push_back({type, count});
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = sets;
  info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  info.pPoolSizes = sizes.data();
  return device.createDescriptorPool(info, "descriptor pool");
}

}  // namespace clouds::detail
