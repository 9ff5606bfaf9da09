#pragma once
// A compute shader with its descriptor set layout (set 0), push constants and pipeline
// variants keyed by specialization constants (constant ids 0..n-1): feature toggles are
// compiled out rather than branched over at run time. Variants are created by prepare(),
// outside command recording; find() only looks them up, so recording never creates one.
#include <vulkan/vulkan.h>

#include <array>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "vkfx/device_context.h"

namespace vkfx {

// Specialization constant values (constant ids 0..count-1); fixed size so looking up a
// variant every frame allocates nothing.
struct SpecializationKey {
  std::array<std::uint32_t, 16> values{};
  std::uint32_t count = 0;
  auto operator<=>(const SpecializationKey&) const = default;
};

// One descriptor of set 0: its binding slot (cloud_types.h) and type.
struct Binding {
  std::uint32_t slot;
  VkDescriptorType type;
};

class ComputeProgram {
 public:
  ComputeProgram(const DeviceContext& context, std::span<const std::uint32_t> spirv,
                 std::span<const Binding> bindings, std::uint32_t pushConstantBytes,
                 std::string name);

  // Creates the variant if it does not exist yet (never during recording).
  VkPipeline prepare(const SpecializationKey& specialization = {});
  // The variant, or VK_NULL_HANDLE when prepare() has not created it.
  VkPipeline find(const SpecializationKey& specialization = {}) const;
  VkPipelineLayout layout() const { return layout_.get(); }
  VkDescriptorSetLayout setLayout() const { return setLayout_.get(); }
  const std::vector<Binding>& bindings() const { return bindings_; }
  const std::string& name() const { return name_; }
  std::size_t variantCount() const { return variants_.size(); }

 private:
  const DeviceContext& context_;
  std::string name_;
  std::vector<Binding> bindings_;
  UniqueShaderModule module_;
  UniqueSetLayout setLayout_;
  UniquePipelineLayout layout_;
  std::map<SpecializationKey, UniquePipeline> variants_;
};

// Fills and writes a descriptor set binding by binding (image infos or buffer infos).
class SetWriter {
 public:
  SetWriter(const DeviceContext& context, VkDescriptorSet set) : context_(context), set_(set) {}
  SetWriter& storageImage(std::uint32_t binding, VkImageView view);
  SetWriter& sampledImage(std::uint32_t binding, VkImageView view, VkSampler sampler,
                          VkImageLayout layout);
  SetWriter& uniformBuffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize size);
  SetWriter& storageBuffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize size);
  void commit();

 private:
  struct Entry {
    std::uint32_t binding;
    VkDescriptorType type;
    VkDescriptorImageInfo image;
    VkDescriptorBufferInfo buffer;
  };
  Entry& add(std::uint32_t binding, VkDescriptorType type);

  // Fixed capacity: descriptor updates happen every frame and must not allocate.
  static constexpr std::size_t kMaxEntries = 20;
  const DeviceContext& context_;
  VkDescriptorSet set_;
  std::array<Entry, kMaxEntries> entries_{};
  std::size_t count_ = 0;
};

}  // namespace vkfx
