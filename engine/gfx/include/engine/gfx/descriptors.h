#pragma once
// Per-frame descriptor sets: an arena of descriptor pools that is reset once the frame that
// used it has retired, and a fixed-capacity writer, so binding resources each frame allocates
// nothing on the heap once the arena has grown to its working size.
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/gfx/device.h"
#include "engine/gfx/pipelines.h"

namespace engine::gfx {

class DescriptorArena {
 public:
  DescriptorArena(Device& device, std::string debugName);
  ~DescriptorArena();
  DescriptorArena(const DescriptorArena&) = delete;
  DescriptorArena& operator=(const DescriptorArena&) = delete;

  // A set valid until reset(). Adds a pool when the current ones are full.
  VkDescriptorSet allocate(VkDescriptorSetLayout layout);
  // Returns every set to the pools. Only when the GPU no longer uses any of them.
  void reset();
  std::size_t poolCount() const { return pools_.size(); }

 private:
  VkDescriptorPool createPool();

  Device& device_;
  std::string debugName_;
  std::vector<VkDescriptorPool> pools_;
  std::size_t current_ = 0;
};

class DescriptorWriter {
 public:
  static constexpr std::size_t kMaxWrites = 16;

  DescriptorWriter& storageImage(std::uint32_t binding, VkImageView view);
  DescriptorWriter& sampledImage(std::uint32_t binding, VkImageView view,
                                 VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  DescriptorWriter& combinedImageSampler(
      std::uint32_t binding, VkImageView view, VkSampler sampler,
      VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  DescriptorWriter& sampler(std::uint32_t binding, VkSampler sampler);
  DescriptorWriter& uniformBuffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                                  VkDeviceSize range = VK_WHOLE_SIZE);
  DescriptorWriter& storageBuffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                                  VkDeviceSize range = VK_WHOLE_SIZE);

  void update(VkDevice device, VkDescriptorSet set) const;
  std::size_t size() const { return count_; }

 private:
  VkWriteDescriptorSet& next(std::uint32_t binding, VkDescriptorType type);

  std::array<VkWriteDescriptorSet, kMaxWrites> writes_{};
  std::array<VkDescriptorImageInfo, kMaxWrites> images_{};
  std::array<VkDescriptorBufferInfo, kMaxWrites> buffers_{};
  std::size_t count_ = 0;
};

// Binds `pipeline` and a fresh set from `arena` filled by `writer`.
void bindPipeline(const Device& device, VkCommandBuffer cmd, const Pipeline& pipeline,
                  DescriptorArena& arena, const DescriptorWriter& writer);

template <typename T>
void pushConstants(VkCommandBuffer cmd, const Pipeline& pipeline, const T& constants) {
  vkCmdPushConstants(cmd, pipeline.layout(), pipeline.pushConstantStages(), 0, sizeof(T),
                     &constants);
}

// Workgroup count covering `size` items with groups of `groupSize`.
constexpr std::uint32_t groupCount(std::uint32_t size, std::uint32_t groupSize) {
  return (size + groupSize - 1) / groupSize;
}

}  // namespace engine::gfx
