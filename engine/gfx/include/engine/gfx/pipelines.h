#pragma once
// Compute and graphics pipelines from embedded SPIR-V, with specialization constants. Each
// pipeline owns one descriptor set layout (set 0) built from a declared binding list, a push
// constant range and its layout. The binding list also says which resources the pipeline will
// see (formats, view types, sampler filtering) so warmUpPipelines() can run it once at load:
// lavapipe JIT-compiles a shader at its first dispatch, per resource-format combination.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/gfx/device.h"

namespace engine::gfx {

struct DescriptorBinding {
  std::uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  // The resource the pipeline will see at run time; warm-up binds a 1-texel stand-in like it.
  VkFormat format = VK_FORMAT_UNDEFINED;             // images: the bound view's format
  VkImageViewType viewType = VK_IMAGE_VIEW_TYPE_2D;  // images: the bound view's type
  VkFilter filter = VK_FILTER_LINEAR;                // samplers
  VkSamplerAddressMode addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;  // samplers
};

// A 32-bit specialization constant (int, uint, float bits or a 0/1 flag).
struct SpecializationConstant {
  std::uint32_t id = 0;
  std::uint32_t value = 0;
};

struct ComputePipelineDesc {
  std::span<const std::uint32_t> spirv;
  std::vector<DescriptorBinding> bindings;
  std::uint32_t pushConstantBytes = 0;
  std::vector<SpecializationConstant> specialization;
  std::string debugName;
};

// Transmitted: colour + destination x alpha, where alpha is the share of what lies behind that
// the fragment lets through (a surface that reflects, scatters and partly transmits, such as
// water over its bed).
enum class BlendMode { Opaque, Alpha, PremultipliedAlpha, Additive, Transmitted };

struct GraphicsPipelineDesc {
  std::span<const std::uint32_t> vertexSpirv;
  std::span<const std::uint32_t> fragmentSpirv;
  std::vector<DescriptorBinding> bindings;
  std::uint32_t pushConstantBytes = 0;
  std::vector<SpecializationConstant> specialization;  // applied to both stages
  std::vector<VkFormat> colorFormats;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  bool depthTest = false;
  bool depthWrite = false;
  VkCompareOp depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reversed-Z: near = 1
  VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
  VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  BlendMode blend = BlendMode::Opaque;
  std::vector<VkVertexInputBindingDescription> vertexBindings;
  std::vector<VkVertexInputAttributeDescription> vertexAttributes;
  std::string debugName;
};

class Pipeline {
 public:
  Pipeline() = default;
  Pipeline(Device& device, const ComputePipelineDesc& desc);
  Pipeline(Device& device, const GraphicsPipelineDesc& desc);
  ~Pipeline() { reset(); }
  Pipeline(Pipeline&& other) noexcept { *this = std::move(other); }
  Pipeline& operator=(Pipeline&& other) noexcept;
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  void reset();
  explicit operator bool() const { return pipeline_ != VK_NULL_HANDLE; }
  VkPipeline vk() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_; }
  VkDescriptorSetLayout setLayout() const { return setLayout_; }
  VkPipelineBindPoint bindPoint() const { return bindPoint_; }
  VkShaderStageFlags pushConstantStages() const { return pushStages_; }
  std::uint32_t pushConstantBytes() const { return pushConstantBytes_; }
  const std::vector<DescriptorBinding>& bindings() const { return bindings_; }
  const std::string& name() const { return name_; }
  // Graphics only: attachment formats and vertex bindings (used by warm-up).
  const std::vector<VkFormat>& colorFormats() const { return colorFormats_; }
  VkFormat depthFormat() const { return depthFormat_; }
  const std::vector<VkVertexInputBindingDescription>& vertexBindings() const {
    return vertexBindings_;
  }

 private:
  void create(Device& device, const ComputePipelineDesc& desc);
  void create(Device& device, const GraphicsPipelineDesc& desc);
  void createLayout(Device& device, const std::vector<DescriptorBinding>& bindings,
                    std::uint32_t pushConstantBytes, VkShaderStageFlags stages);

  Device* device_ = nullptr;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
  VkShaderStageFlags pushStages_ = 0;
  std::uint32_t pushConstantBytes_ = 0;
  std::vector<DescriptorBinding> bindings_;
  std::vector<VkFormat> colorFormats_;
  VkFormat depthFormat_ = VK_FORMAT_UNDEFINED;
  std::vector<VkVertexInputBindingDescription> vertexBindings_;
  std::string name_;
};

// Runs every pipeline once on 1-texel stand-in resources (one dispatch of one workgroup with
// zeroed push constants, or one triangle into 1x1 attachments) and waits, so the driver's
// shader JIT happens at load instead of in the first frames. Shaders must tolerate a zero
// extent in their push constants (they bounds-check against it). Returns the milliseconds spent.
double warmUpPipelines(Device& device, std::span<const Pipeline* const> pipelines);

}  // namespace engine::gfx
