#pragma once
// The water on the GPU (a scene's lake or sea; shaders/water_surface.h): a square around the
// camera at the water's level, drawn in the scene pass in two parts (the far part before the
// terrain, the near part after it, blended over the bed by what the water lets through), writing
// depth so that the clouds are marched to its surface. Variants as the terrain's: hazed by the
// atmosphere's aerial perspective and reflecting its sky map (the clouds' sky light when they make
// one), or fogged under the gradient sky; lit through the terrain's sunlight map under cloud
// shadows; in a storm's scene, lit by the brightest flash in progress as the terrain is.
#include <vector>

#include "bindings.h"
#include "engine/gfx/pipelines.h"
#include "engine/gfx/resources.h"
#include "render/scene_surface.h"

namespace sample {

class WaterRenderer {
 public:
  static constexpr std::uint32_t kFrameBinding = engine::shaders::kWaterFrameBinding;
  static constexpr std::uint32_t kHazeBinding = engine::shaders::kWaterHazeBinding;
  static constexpr std::uint32_t kSunlightBinding = engine::shaders::kWaterSunlightBinding;
  static constexpr std::uint32_t kSkyBinding = engine::shaders::kWaterSkyBinding;
  // Specialization constant: 1 lights the water with the brightest flash in progress.
  static constexpr std::uint32_t kLightningConstant = 0;

  // `aerialPerspective`: hazed by a feature's aerial perspective and reflecting its sky map
  // (else fogged, reflecting the gradient sky). `cloudShadows`: the sun through the terrain's
  // sunlight map. `lightning`: a storm's flashes light it (SceneFrame::flash): a second
  // pipeline, drawn with in the frames with a flash in progress (setFlashing()).
  WaterRenderer(engine::gfx::Device& device, VkFormat hdrFormat, VkFormat depthFormat,
                bool aerialPerspective, bool cloudShadows, bool lightning);

  // This frame's pipeline: the lightning variant only while a flash is in progress.
  const engine::gfx::Pipeline& pipeline() const { return pipelines_.current(); }
  // Every pipeline it may draw with (to warm up and to describe).
  std::vector<const engine::gfx::Pipeline*> pipelines() const { return pipelines_.all(); }
  // Whether this frame has a flash in progress (SceneFrame::flashRadiance is not 0).
  void setFlashing(bool flashing) { pipelines_.setFlashing(flashing); }
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
  // The plain pipeline's description (FlashVariants makes the lightning one from it).
  static engine::gfx::GraphicsPipelineDesc describe(bool aerialPerspective, bool cloudShadows,
                                                    VkFormat hdrFormat, VkFormat depthFormat);

  bool aerialPerspective_ = false;
  bool cloudShadows_ = false;
  FlashVariants pipelines_;
  engine::gfx::Sampler clamped_;
  engine::gfx::Sampler repeating_;
};

}  // namespace sample
