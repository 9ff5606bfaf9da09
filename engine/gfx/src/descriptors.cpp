#include "engine/gfx/descriptors.h"

#include "engine/core/error.h"
#include "engine/gfx/vk_check.h"

namespace engine::gfx {

DescriptorArena::DescriptorArena(Device& device, std::string debugName)
    : device_(device), debugName_(std::move(debugName)) {}

DescriptorArena::~DescriptorArena() {
  for (VkDescriptorPool pool : pools_) {
    device_.release(VK_OBJECT_TYPE_DESCRIPTOR_POOL, handleBits(pool));
  }
}

VkDescriptorPool DescriptorArena::createPool() {
  // Sized for a frame's worth of passes; more pools are added if a frame needs more.
  const VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 256},          {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 256},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 256}, {VK_DESCRIPTOR_TYPE_SAMPLER, 64},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 128},         {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 128},
  };
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = 128;
  info.poolSizeCount = static_cast<std::uint32_t>(std::size(sizes));
  info.pPoolSizes = sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  GFX_CHECK(vkCreateDescriptorPool(device_.vk(), &info, nullptr, &pool));
  setName(device_, pool, debugName_.c_str());
  return pool;
}

VkDescriptorSet DescriptorArena::allocate(VkDescriptorSetLayout layout) {
  for (;;) {
    if (current_ == pools_.size()) pools_.push_back(createPool());
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorPool = pools_[current_];
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    const VkResult result = vkAllocateDescriptorSets(device_.vk(), &info, &set);
    if (result == VK_SUCCESS) return set;
    if (result != VK_ERROR_OUT_OF_POOL_MEMORY && result != VK_ERROR_FRAGMENTED_POOL) {
      throwVulkanError(result, "vkAllocateDescriptorSets", __FILE__, __LINE__);
    }
    ++current_;  // this pool is full; move to the next (created on demand)
  }
}

void DescriptorArena::reset() {
  for (VkDescriptorPool pool : pools_) vkResetDescriptorPool(device_.vk(), pool, 0);
  current_ = 0;
}

VkWriteDescriptorSet& DescriptorWriter::next(std::uint32_t binding, VkDescriptorType type) {
  if (count_ == kMaxWrites) throw Error("DescriptorWriter: more than 16 bindings");
  VkWriteDescriptorSet& write = writes_[count_];
  write = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  ++count_;
  return write;
}

DescriptorWriter& DescriptorWriter::storageImage(std::uint32_t binding, VkImageView view) {
  const std::size_t i = count_;
  next(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
  images_[i] = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
  return *this;
}

DescriptorWriter& DescriptorWriter::sampledImage(std::uint32_t binding, VkImageView view,
                                                 VkImageLayout layout) {
  const std::size_t i = count_;
  next(binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
  images_[i] = {VK_NULL_HANDLE, view, layout};
  return *this;
}

DescriptorWriter& DescriptorWriter::combinedImageSampler(std::uint32_t binding, VkImageView view,
                                                         VkSampler sampler, VkImageLayout layout) {
  const std::size_t i = count_;
  next(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  images_[i] = {sampler, view, layout};
  return *this;
}

DescriptorWriter& DescriptorWriter::sampler(std::uint32_t binding, VkSampler sampler) {
  const std::size_t i = count_;
  next(binding, VK_DESCRIPTOR_TYPE_SAMPLER);
  images_[i] = {sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
  return *this;
}

DescriptorWriter& DescriptorWriter::uniformBuffer(std::uint32_t binding, VkBuffer buffer,
                                                  VkDeviceSize offset, VkDeviceSize range) {
  const std::size_t i = count_;
  next(binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  buffers_[i] = {buffer, offset, range};
  return *this;
}

DescriptorWriter& DescriptorWriter::storageBuffer(std::uint32_t binding, VkBuffer buffer,
                                                  VkDeviceSize offset, VkDeviceSize range) {
  const std::size_t i = count_;
  next(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  buffers_[i] = {buffer, offset, range};
  return *this;
}

void DescriptorWriter::update(VkDevice device, VkDescriptorSet set) const {
  std::array<VkWriteDescriptorSet, kMaxWrites> writes = writes_;
  for (std::size_t i = 0; i < count_; ++i) {
    writes[i].dstSet = set;
    const VkDescriptorType type = writes[i].descriptorType;
    if (type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER) {
      writes[i].pBufferInfo = &buffers_[i];
    } else {
      writes[i].pImageInfo = &images_[i];
    }
  }
  vkUpdateDescriptorSets(device, static_cast<std::uint32_t>(count_), writes.data(), 0, nullptr);
}

void bindPipeline(const Device& device, VkCommandBuffer cmd, const Pipeline& pipeline,
                  DescriptorArena& arena, const DescriptorWriter& writer) {
  vkCmdBindPipeline(cmd, pipeline.bindPoint(), pipeline.vk());
  if (pipeline.bindings().empty()) return;
  const VkDescriptorSet set = arena.allocate(pipeline.setLayout());
  writer.update(device.vk(), set);
  vkCmdBindDescriptorSets(cmd, pipeline.bindPoint(), pipeline.layout(), 0, 1, &set, 0, nullptr);
}

}  // namespace engine::gfx
