#include "engine/gfx/pipelines.h"

#include <array>
#include <utility>

#include "engine/core/error.h"
#include "engine/gfx/vk_check.h"

namespace engine::gfx {
namespace {

// A shader module for the length of a pipeline's creation, destroyed however that ends.
class ScopedModule {
 public:
  ScopedModule(Device& device, std::span<const std::uint32_t> spirv, const std::string& name)
      : device_(device.vk()) {
    require(!spirv.empty(), "Pipeline '" + name + "'", "empty SPIR-V");
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    GFX_CHECK(vkCreateShaderModule(device_, &info, nullptr, &module_));
  }
  ~ScopedModule() { vkDestroyShaderModule(device_, module_, nullptr); }
  ScopedModule(const ScopedModule&) = delete;
  ScopedModule& operator=(const ScopedModule&) = delete;
  VkShaderModule get() const { return module_; }

 private:
  VkDevice device_;
  VkShaderModule module_ = VK_NULL_HANDLE;
};

// Owns the map entries and data VkSpecializationInfo points into.
struct Specialization {
  std::vector<VkSpecializationMapEntry> entries;
  std::vector<std::uint32_t> data;
  VkSpecializationInfo info{};

  explicit Specialization(const std::vector<SpecializationConstant>& constants) {
    for (const auto& c : constants) {
      entries.push_back({c.id, static_cast<std::uint32_t>(data.size() * sizeof(std::uint32_t)),
                         sizeof(std::uint32_t)});
      data.push_back(c.value);
    }
    info.mapEntryCount = static_cast<std::uint32_t>(entries.size());
    info.pMapEntries = entries.data();
    info.dataSize = data.size() * sizeof(std::uint32_t);
    info.pData = data.data();
  }
  const VkSpecializationInfo* get() const { return entries.empty() ? nullptr : &info; }
};

}  // namespace

void Pipeline::createLayout(Device& device, const std::vector<DescriptorBinding>& bindings,
                            std::uint32_t pushConstantBytes, VkShaderStageFlags stages) {
  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  for (const auto& b : bindings) {
    VkDescriptorSetLayoutBinding lb{};
    lb.binding = b.binding;
    lb.descriptorType = b.type;
    lb.descriptorCount = 1;
    lb.stageFlags = stages;
    layoutBindings.push_back(lb);
  }
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = static_cast<std::uint32_t>(layoutBindings.size());
  setInfo.pBindings = layoutBindings.data();
  GFX_CHECK(vkCreateDescriptorSetLayout(device.vk(), &setInfo, nullptr, &setLayout_));
  setName(device, setLayout_, (name_ + " set layout").c_str());

  VkPushConstantRange range{stages, 0, pushConstantBytes};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout_;
  layoutInfo.pushConstantRangeCount = pushConstantBytes > 0 ? 1u : 0u;
  layoutInfo.pPushConstantRanges = &range;
  GFX_CHECK(vkCreatePipelineLayout(device.vk(), &layoutInfo, nullptr, &layout_));
  setName(device, layout_, (name_ + " layout").c_str());
  pushStages_ = stages;
  pushConstantBytes_ = pushConstantBytes;
  bindings_ = bindings;
}

// The destructor does not run for a constructor that throws, so each constructor gives back
// what it made so far itself.
Pipeline::Pipeline(Device& device, const ComputePipelineDesc& desc)
    : device_(&device), bindPoint_(VK_PIPELINE_BIND_POINT_COMPUTE), name_(desc.debugName) {
  try {
    create(device, desc);
  } catch (...) {
    reset();
    throw;
  }
}

Pipeline::Pipeline(Device& device, const GraphicsPipelineDesc& desc)
    : device_(&device), bindPoint_(VK_PIPELINE_BIND_POINT_GRAPHICS), name_(desc.debugName) {
  try {
    create(device, desc);
  } catch (...) {
    reset();
    throw;
  }
}

void Pipeline::create(Device& device, const ComputePipelineDesc& desc) {
  createLayout(device, desc.bindings, desc.pushConstantBytes, VK_SHADER_STAGE_COMPUTE_BIT);
  const ScopedModule module(device, desc.spirv, name_);
  const Specialization specialization(desc.specialization);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = VkPipelineShaderStageCreateInfo{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module.get();
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = specialization.get();
  info.layout = layout_;
  const VkResult result =
      vkCreateComputePipelines(device.vk(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_);
  if (result != VK_SUCCESS) {
    throwVulkanError(result, ("vkCreateComputePipelines for '" + desc.debugName + "'").c_str(),
                     __FILE__, __LINE__);
  }
  setName(device, pipeline_, name_.c_str());
}

void Pipeline::create(Device& device, const GraphicsPipelineDesc& desc) {
  createLayout(device, desc.bindings, desc.pushConstantBytes,
               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  colorFormats_ = desc.colorFormats;
  depthFormat_ = desc.depthFormat;
  vertexBindings_ = desc.vertexBindings;

  const ScopedModule vertex(device, desc.vertexSpirv, name_);
  const ScopedModule fragment(device, desc.fragmentSpirv, name_);
  const Specialization specialization(desc.specialization);
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  for (auto& s : stages) {
    s.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    s.pName = "main";
    s.pSpecializationInfo = specialization.get();
  }
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex.get();
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment.get();

  VkPipelineVertexInputStateCreateInfo vertexInput{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount =
      static_cast<std::uint32_t>(desc.vertexBindings.size());
  vertexInput.pVertexBindingDescriptions = desc.vertexBindings.data();
  vertexInput.vertexAttributeDescriptionCount =
      static_cast<std::uint32_t>(desc.vertexAttributes.size());
  vertexInput.pVertexAttributeDescriptions = desc.vertexAttributes.data();

  VkPipelineInputAssemblyStateCreateInfo inputAssembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  inputAssembly.topology = desc.topology;

  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = desc.cullMode;
  raster.frontFace = desc.frontFace;
  raster.lineWidth = 1.0f;

  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

  VkPipelineDepthStencilStateCreateInfo depth{
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = desc.depthTest ? VK_TRUE : VK_FALSE;
  depth.depthWriteEnable = desc.depthWrite ? VK_TRUE : VK_FALSE;
  depth.depthCompareOp = desc.depthCompare;

  VkPipelineColorBlendAttachmentState blendState{};
  blendState.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                              VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  if (desc.blend != BlendMode::Opaque) {
    blendState.blendEnable = VK_TRUE;
    blendState.srcColorBlendFactor =
        desc.blend == BlendMode::Alpha ? VK_BLEND_FACTOR_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
    blendState.dstColorBlendFactor = desc.blend == BlendMode::Additive ? VK_BLEND_FACTOR_ONE
                                     : desc.blend == BlendMode::Transmitted
                                         ? VK_BLEND_FACTOR_SRC_ALPHA
                                         : VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blendState.colorBlendOp = VK_BLEND_OP_ADD;
    blendState.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blendState.dstAlphaBlendFactor = blendState.dstColorBlendFactor;
    if (desc.blend == BlendMode::Transmitted) {
      // The alpha is the fragment's transmittance, not coverage: the destination's alpha stays.
      blendState.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
      blendState.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    }
    blendState.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  std::vector<VkPipelineColorBlendAttachmentState> blendStates(desc.colorFormats.size(),
                                                               blendState);
  VkPipelineColorBlendStateCreateInfo blend{
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = static_cast<std::uint32_t>(blendStates.size());
  blend.pAttachments = blendStates.data();

  const std::array<VkDynamicState, 2> dynamicStates{VK_DYNAMIC_STATE_VIEWPORT,
                                                    VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = static_cast<std::uint32_t>(dynamicStates.size());
  dynamic.pDynamicStates = dynamicStates.data();

  // Dynamic rendering: attachment formats instead of a render pass.
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = static_cast<std::uint32_t>(desc.colorFormats.size());
  rendering.pColorAttachmentFormats = desc.colorFormats.data();
  rendering.depthAttachmentFormat = desc.depthFormat;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.pNext = &rendering;
  info.stageCount = static_cast<std::uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &inputAssembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout_;
  const VkResult result =
      vkCreateGraphicsPipelines(device.vk(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_);
  if (result != VK_SUCCESS) {
    throwVulkanError(result, ("vkCreateGraphicsPipelines for '" + desc.debugName + "'").c_str(),
                     __FILE__, __LINE__);
  }
  setName(device, pipeline_, name_.c_str());
}

Pipeline& Pipeline::operator=(Pipeline&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, nullptr);
    pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    setLayout_ = std::exchange(other.setLayout_, VK_NULL_HANDLE);
    bindPoint_ = other.bindPoint_;
    pushStages_ = other.pushStages_;
    pushConstantBytes_ = other.pushConstantBytes_;
    bindings_ = std::move(other.bindings_);
    colorFormats_ = std::move(other.colorFormats_);
    depthFormat_ = other.depthFormat_;
    vertexBindings_ = std::move(other.vertexBindings_);
    name_ = std::move(other.name_);
  }
  return *this;
}

void Pipeline::reset() {
  if (device_ != nullptr) {
    // Released in dependency order: the pipeline, then its layout, then the set layout.
    device_->release(VK_OBJECT_TYPE_PIPELINE, handleBits(pipeline_));
    device_->release(VK_OBJECT_TYPE_PIPELINE_LAYOUT, handleBits(layout_));
    device_->release(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, handleBits(setLayout_));
  }
  device_ = nullptr;
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  setLayout_ = VK_NULL_HANDLE;
}

}  // namespace engine::gfx
