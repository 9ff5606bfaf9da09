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

}  // namespace sample
