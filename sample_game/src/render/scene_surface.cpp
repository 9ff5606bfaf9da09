#include "render/scene_surface.h"

#include "render/terrain_sunlight.h"

namespace sample {

void describeSceneSurface(engine::gfx::GraphicsPipelineDesc& desc, VkFormat hdrFormat,
                          VkFormat depthFormat, bool aerialPerspective, std::uint32_t hazeBinding,
                          bool cloudShadows, std::uint32_t sunlightBinding) {
  if (aerialPerspective) {
    desc.bindings.push_back({hazeBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                             VK_FORMAT_R16G16B16A16_SFLOAT, VK_IMAGE_VIEW_TYPE_3D});
  }
  if (cloudShadows) {
    desc.bindings.push_back({sunlightBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                             TerrainSunlight::kFormat, VK_IMAGE_VIEW_TYPE_2D});
  }
  desc.colorFormats = {hdrFormat};
  desc.depthFormat = depthFormat;
  desc.depthTest = true;
  desc.depthWrite = true;
  desc.cullMode = VK_CULL_MODE_NONE;
}

FlashVariants::FlashVariants(engine::gfx::Device& device, engine::gfx::GraphicsPipelineDesc desc,
                             std::uint32_t lightningConstant, bool lightning) {
  desc.specialization.push_back({lightningConstant, 0u});
  plain_ = engine::gfx::Pipeline(device, desc);
  if (lightning) {
    desc.specialization.back().value = 1u;
    desc.debugName += " (lightning)";
    lightning_.emplace(device, desc);
  }
}

std::vector<const engine::gfx::Pipeline*> FlashVariants::all() const {
  std::vector<const engine::gfx::Pipeline*> pipelines = {&plain_};
  if (lightning_) pipelines.push_back(&*lightning_);
  return pipelines;
}

}  // namespace sample
