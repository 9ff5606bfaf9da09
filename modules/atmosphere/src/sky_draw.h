#pragma once
// The graphics pipeline drawSky() binds: sky_draw.vert/.frag for the host's dynamic-rendering
// pass (its colour and depth formats), depth test EQUAL against the far plane and no depth
// write, so that drawn after the opaque geometry it shades only the pixels left empty. Viewport
// and scissor are dynamic. Made at creation when the host asks for it (CreateInfo::skyPass).
#include <vulkan/vulkan.h>

#include "atmosphere_types.h"
#include "kit.h"

namespace atmosphere::detail {

class SkyDraw {
 public:
  // Its descriptor set: the frame's uniforms (both stages) and the sky view (fragment). The
  // module's descriptor pool is sized from these.
  struct SetBinding {
    std::uint32_t slot;
    VkDescriptorType type;
    VkShaderStageFlags stages;
  };
  static constexpr SetBinding kBindings[] = {
      {shader::kBindingUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
      {shader::kBindingSkyView, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
       VK_SHADER_STAGE_FRAGMENT_BIT},
  };

  SkyDraw(const DeviceContext& device, VkFormat colorFormat, VkFormat depthFormat, bool reversedZ);
  VkPipeline pipeline() const { return pipeline_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }
  VkDescriptorSetLayout setLayout() const { return setLayout_.get(); }

 private:
  vkfx::UniqueSetLayout setLayout_;
  vkfx::UniquePipelineLayout layout_;
  vkfx::UniqueShaderModule vertex_;
  vkfx::UniqueShaderModule fragment_;
  vkfx::UniquePipeline pipeline_;
};

}  // namespace atmosphere::detail
