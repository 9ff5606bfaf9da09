#pragma once
// The graphics pipeline state the scene pass's surfaces (the terrain, the water) share.
#include <cstdint>

#include "engine/gfx/pipelines.h"

namespace sample {

// Drawn into the HDR colour with a reversed-Z depth test and write, both faces; with
// `aerialPerspective` the haze volume at `hazeBinding`, with `cloudShadows` the terrain's
// sunlight map at `sunlightBinding` (the variants that read them). Adds to `desc.bindings`.
void describeSceneSurface(engine::gfx::GraphicsPipelineDesc& desc, VkFormat hdrFormat,
                          VkFormat depthFormat, bool aerialPerspective, std::uint32_t hazeBinding,
                          bool cloudShadows, std::uint32_t sunlightBinding);

}  // namespace sample
