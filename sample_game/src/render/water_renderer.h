#pragma once
// The water on the GPU (a scene's lake or sea; shaders/water_surface.h): a square around the
// camera at the water's level, drawn in the scene pass in two parts (the far part before the
// terrain, the near part after it, blended over the bed by what the water lets through), writing
// depth so that the clouds are marched to its surface. Variants as the terrain's: hazed by the
// atmosphere's aerial perspective and reflecting its sky map (the clouds' sky light when they make
// one), or fogged under the gradient sky; lit through the terrain's sunlight map under cloud
// shadows.
#include <vector>

#include "bindings.h"
#include "engine/gfx/pipelines.h"
#include "engine/gfx/resources.h"

namespace sample {

class WaterRenderer {
 public:
  static constexpr std::uint32_t kFrameBinding = engine::shaders::kWaterFrameBinding;
  static constexpr std::uint32_t kHazeBinding = engine::shaders::kWaterHazeBinding;
  static constexpr std::uint32_t kSunlightBinding = engine::shaders::kWaterSunlightBinding;
  static constexpr std::uint32_t kSkyBinding = engine::shaders::kWaterSkyBinding;

  // `aerialPerspective`: hazed by a feature's aerial perspective and reflecting its sky map
  // (else fogged, reflecting the gradient sky). `cloudShadows`: the sun through the terrain's
  // sunlight map.
  WaterRenderer(engine::gfx::Device& device, VkFormat hdrFormat, VkFormat depthFormat,
                bool aerialPerspective, bool cloudShadows);

  const engine::gfx::Pipeline& pipeline() const { return pipeline_; }
  bool hazedByAerialPerspective() const { return aerialPerspective_; }
  bool shadowedByClouds() const { return cloudShadows_; }
  // Linear, clamped: the aerial perspective's and the sunlight map's.
  VkSampler clampedSampler() const { return clamped_.vk(); }
  // Linear, repeating: the sky map's (its azimuth wraps).
  VkSampler skySampler() const { return repeating_.vk(); }
  // The water where the bed shows through it (within SceneFrame::water.z of the camera): drawn
  // after the terrain, over its bed.
  void drawNear(VkCommandBuffer cmd) const;
  // The rest, out to the horizon: drawn before the terrain, it hides the bed under it (less
  // than 1/255 of whose light would show), whose shading is then skipped.
  void drawFar(VkCommandBuffer cmd) const;

 private:
  bool aerialPerspective_ = false;
  bool cloudShadows_ = false;
  engine::gfx::Sampler clamped_;
  engine::gfx::Sampler repeating_;
  engine::gfx::Pipeline pipeline_;
};

}  // namespace sample
