#include "vkfx/compute_program.h"

#include <cstdlib>

namespace vkfx {

ComputeProgram::ComputeProgram(const DeviceContext& context, std::span<const std::uint32_t> spirv,
                               std::span<const Binding> bindings, std::uint32_t pushConstantBytes,
                               std::string name)
    : context_(context), name_(std::move(name)), bindings_(bindings.begin(), bindings.end()) {
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = spirv.size_bytes();
  moduleInfo.pCode = spirv.data();
  module_ = context.createShaderModule(moduleInfo, name_);

  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  for (const Binding& binding : bindings_) {
    layoutBindings.push_back({binding.slot, binding.type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  }
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = static_cast<std::uint32_t>(layoutBindings.size());
  setInfo.pBindings = layoutBindings.data();
  setLayout_ = context.createSetLayout(setInfo, name_ + " set layout");

  const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes};
  const VkDescriptorSetLayout setLayout = setLayout_.get();
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  layoutInfo.pushConstantRangeCount = pushConstantBytes > 0 ? 1u : 0u;
  layoutInfo.pPushConstantRanges = &range;
  layout_ = context.createPipelineLayout(layoutInfo, name_ + " layout");
}

VkPipeline ComputeProgram::find(const SpecializationKey& specialization) const {
  const auto it = variants_.find(specialization);
  return it == variants_.end() ? VK_NULL_HANDLE : it->second.get();
}

VkPipeline ComputeProgram::prepare(const SpecializationKey& specialization) {
  if (const VkPipeline existing = find(specialization)) return existing;
  std::vector<VkSpecializationMapEntry> entries;
  for (std::uint32_t i = 0; i < specialization.count; ++i) {
    entries.push_back({i, i * 4u, 4u});
  }
  VkSpecializationInfo specializationInfo{};
  specializationInfo.mapEntryCount = static_cast<std::uint32_t>(entries.size());
  specializationInfo.pMapEntries = entries.data();
  specializationInfo.dataSize = specialization.count * sizeof(std::uint32_t);
  specializationInfo.pData = specialization.values.data();

  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module_.get();
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = entries.empty() ? nullptr : &specializationInfo;
  info.layout = layout_.get();
  std::string variantName = name_;
  for (std::uint32_t i = 0; i < specialization.count; ++i) {
    variantName += " " + std::to_string(specialization.values[i]);
  }
  UniquePipeline pipeline = context_.createComputePipeline(info, variantName);
  const VkPipeline handle = pipeline.get();
  variants_.emplace(specialization, std::move(pipeline));
  return handle;
}

SetWriter::Entry& SetWriter::add(std::uint32_t binding, VkDescriptorType type) {
  // More bindings than any pass has: a programming error, not a runtime condition (recording
  // must not fail halfway).
  if (count_ == kMaxEntries) std::abort();
  Entry& e = entries_[count_++];
  e = Entry{binding, type, {}, {}};
  return e;
}

SetWriter& SetWriter::storageImage(std::uint32_t binding, VkImageView view) {
  add(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE).image = {VK_NULL_HANDLE, view,
                                                          VK_IMAGE_LAYOUT_GENERAL};
  return *this;
}

SetWriter& SetWriter::sampledImage(std::uint32_t binding, VkImageView view, VkSampler sampler,
                                   VkImageLayout layout) {
  add(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER).image = {sampler, view, layout};
  return *this;
}

SetWriter& SetWriter::uniformBuffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize size) {
  add(binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER).buffer = {buffer, 0, size};
  return *this;
}

SetWriter& SetWriter::storageBuffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize size) {
  add(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).buffer = {buffer, 0, size};
  return *this;
}

void SetWriter::commit() {
  std::array<VkWriteDescriptorSet, kMaxEntries> writes{};
  for (std::size_t i = 0; i < count_; ++i) {
    const Entry& e = entries_[i];
    VkWriteDescriptorSet& write = writes[i];
    write = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set_;
    write.dstBinding = e.binding;
    write.descriptorCount = 1;
    write.descriptorType = e.type;
    const bool isBuffer =
        e.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || e.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    if (isBuffer) {
      write.pBufferInfo = &e.buffer;
    } else {
      write.pImageInfo = &e.image;
    }
  }
  context_.fn().vkUpdateDescriptorSets(context_.device(), static_cast<std::uint32_t>(count_),
                                       writes.data(), 0, nullptr);
  count_ = 0;
}

}  // namespace vkfx
