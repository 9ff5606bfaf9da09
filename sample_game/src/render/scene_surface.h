#pragma once
// What the scene pass's surfaces (the terrain, the water) share: their graphics pipeline state,
// and their lightning variants.
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/gfx/pipelines.h"

namespace sample {

// Drawn into the HDR colour with a reversed-Z depth test and write, both faces; with
// `aerialPerspective` the haze volume at `hazeBinding`, with `cloudShadows` the terrain's
// sunlight map at `sunlightBinding` (the variants that read them). Adds to `desc.bindings`.
void describeSceneSurface(engine::gfx::GraphicsPipelineDesc& desc, VkFormat hdrFormat,
                          VkFormat depthFormat, bool aerialPerspective, std::uint32_t hazeBinding,
                          bool cloudShadows, std::uint32_t sunlightBinding);

// A surface's pipeline and, in a storm's scene, its lightning variant: the same with the
// specialization constant `lightningConstant` at 1 (0 in the plain one), drawn only in the
// frames with a flash in progress, so that a storm costs the surface nothing between flashes.
class FlashVariants {
 public:
  FlashVariants() = default;  // none yet
  // `desc`'s other specialization constants apply to both.
  FlashVariants(engine::gfx::Device& device, engine::gfx::GraphicsPipelineDesc desc,
                std::uint32_t lightningConstant, bool lightning);

  // This frame's pipeline.
  const engine::gfx::Pipeline& current() const {
    return flashing_ && lightning_ ? *lightning_ : plain_;
  }
  // Every pipeline it may draw with (to warm up and to describe).
  std::vector<const engine::gfx::Pipeline*> all() const;
  // Whether this frame has a flash in progress (SceneFrame::flashRadiance is not 0).
  void setFlashing(bool flashing) { flashing_ = flashing; }

 private:
  engine::gfx::Pipeline plain_;
  std::optional<engine::gfx::Pipeline> lightning_;  // a storm's scene only
  bool flashing_ = false;
};

}  // namespace sample
