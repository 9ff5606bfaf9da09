#include "compute_program.h"

namespace clouds::detail {

ComputeProgram::ComputeProgram(const DeviceContext& context, std::span<const std::uint32_t> spirv,
                               std::vector<VkDescriptorType> bindings,
                               std::uint32_t pushConstantBytes, std::string name)
    : context_(context), name_(std::move(name)), bindings_(std::move(bindings)) {
  const auto& fn = context.fn();
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = spirv.size_bytes();
  moduleInfo.pCode = spirv.data();
  check(fn.vkCreateShaderModule(context.device(), &moduleInfo, nullptr, &module_),
        "vkCreateShaderModule");
  context.name(VK_OBJECT_TYPE_SHADER_MODULE, bits(module_), name_);

  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  for (std::uint32_t i = 0; i < bindings_.size(); ++i) {
    layoutBindings.push_back({i, bindings_[i], 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  }
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = static_cast<std::uint32_t>(layoutBindings.size());
  setInfo.pBindings = layoutBindings.data();
  check(fn.vkCreateDescriptorSetLayout(context.device(), &setInfo, nullptr, &setLayout_),
        "vkCreateDescriptorSetLayout");
  context.name(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, bits(setLayout_), name_ + " set layout");

  const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout_;
  layoutInfo.pushConstantRangeCount = pushConstantBytes > 0 ? 1u : 0u;
  layoutInfo.pPushConstantRanges = &range;
  check(fn.vkCreatePipelineLayout(context.device(), &layoutInfo, nullptr, &layout_),
        "vkCreatePipelineLayout");
  context.name(VK_OBJECT_TYPE_PIPELINE_LAYOUT, bits(layout_), name_ + " layout");
}

ComputeProgram::~ComputeProgram() {
  const auto& fn = context_.fn();
  for (auto& [key, pipeline] : variants_) fn.vkDestroyPipeline(context_.device(), pipeline, nullptr);
  fn.vkDestroyPipelineLayout(context_.device(), layout_, nullptr);
  fn.vkDestroyDescriptorSetLayout(context_.device(), setLayout_, nullptr);
  fn.vkDestroyShaderModule(context_.device(), module_, nullptr);
}

VkPipeline ComputeProgram::variant(const SpecializationKey& specialization) {
  if (auto it = variants_.find(specialization); it != variants_.end()) return it->second;
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
  info.stage.module = module_;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = entries.empty() ? nullptr : &specializationInfo;
  info.layout = layout_;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(context_.fn().vkCreateComputePipelines(context_.device(), VK_NULL_HANDLE, 1, &info, nullptr,
                                               &pipeline),
        "vkCreateComputePipelines");
  std::string variantName = name_;
  for (std::uint32_t i = 0; i < specialization.count; ++i) {
    variantName += " " + std::to_string(specialization.values[i]);
  }
  context_.name(VK_OBJECT_TYPE_PIPELINE, bits(pipeline), variantName);
  variants_.emplace(specialization, pipeline);
  return pipeline;
}

SetWriter::Entry& SetWriter::add(std::uint32_t binding, VkDescriptorType type) {
  if (count_ == kMaxEntries) throw ModuleError("clouds: too many descriptor writes");
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
    const bool isBuffer = e.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER ||
                          e.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
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

}  // namespace clouds::detail
