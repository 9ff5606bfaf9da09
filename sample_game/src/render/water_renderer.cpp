#include "render/water_renderer.h"

#include "render/scene_surface.h"
#include "sample_shaders/water.frag.spv.h"
#include "sample_shaders/water.vert.spv.h"
#include "sample_shaders/water_hazed.frag.spv.h"
#include "sample_shaders/water_hazed_shadowed.frag.spv.h"
#include "sample_shaders/water_shadowed.frag.spv.h"

namespace sample {

using namespace engine;

WaterRenderer::WaterRenderer(gfx::Device& device, VkFormat hdrFormat, VkFormat depthFormat,
                             bool aerialPerspective, bool cloudShadows, bool lightning)
    : aerialPerspective_(aerialPerspective),
      cloudShadows_(cloudShadows),
      pipelines_(device, describe(aerialPerspective, cloudShadows, hdrFormat, depthFormat),
                 kLightningConstant, lightning) {
  gfx::SamplerDesc clamped;
  clamped.debugName = "water linear clamped";
  clamped_ = gfx::Sampler(device, clamped);
  if (aerialPerspective) {
    gfx::SamplerDesc repeating;
    repeating.addressMode = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    repeating.debugName = "water sky linear repeating";
    repeating_ = gfx::Sampler(device, repeating);
  }
}

gfx::GraphicsPipelineDesc WaterRenderer::describe(bool aerialPerspective, bool cloudShadows,
                                                  VkFormat hdrFormat, VkFormat depthFormat) {
  using Spirv = std::span<const std::uint32_t>;
  gfx::GraphicsPipelineDesc desc;
  desc.vertexSpirv = water_vert_spv;
  if (aerialPerspective) {
    desc.fragmentSpirv =
        cloudShadows ? Spirv(water_hazed_shadowed_frag_spv) : Spirv(water_hazed_frag_spv);
  } else {
    desc.fragmentSpirv = cloudShadows ? Spirv(water_shadowed_frag_spv) : Spirv(water_frag_spv);
  }
  desc.bindings = {{kFrameBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
  if (aerialPerspective) {
    desc.bindings.push_back({kSkyBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                             VK_FORMAT_R16G16B16A16_SFLOAT, VK_IMAGE_VIEW_TYPE_2D, VK_FILTER_LINEAR,
                             VK_SAMPLER_ADDRESS_MODE_REPEAT});
  }
  // It writes depth: the clouds stop at the water (water_fragment.glsl).
  describeSceneSurface(desc, hdrFormat, depthFormat, aerialPerspective, kHazeBinding, cloudShadows,
                       kSunlightBinding);
  desc.blend = gfx::BlendMode::Transmitted;
  desc.debugName = cloudShadows ? "water (cloud shadows)" : "water";
  return desc;
}

// water.vert's vertices: 0-5 the near square, 6-29 the far ring.
void WaterRenderer::drawNear(VkCommandBuffer cmd) const {
  vkCmdDraw(cmd, 6, 1, 0, 0);
}

void WaterRenderer::drawFar(VkCommandBuffer cmd) const {
  vkCmdDraw(cmd, 24, 1, 6, 0);
}

}  // namespace sample
