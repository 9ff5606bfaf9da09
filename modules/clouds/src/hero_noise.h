#pragma once
// The hero clouds' detail noise (Settings::heroDetail Uprezzed; cloud_noise.h's
// heroNoiseTexel(), read by cloud_hero.h's heroDensity()): a kHeroNoiseSize^3 RGBA8 image with
// its mip chain above level 0 (cloud_sampling.h's noiseLevelOrigin()), generated on the GPU by
// the first frame that wants it. A context without hero clouds, or whose clouds keep their
// voxels smooth, never makes it.
#include <cstdint>

#include "kit.h"

namespace clouds::detail {

class HeroNoise {
 public:
  explicit HeroNoise(const DeviceContext& device);

  // Records the generation with `seed`: level 0 by `generator` (hero_noise.comp), then each
  // level from the one below by `mip` (hero_noise_mip.comp), each with its descriptor set
  // (written here). What follows in the command buffer may read the image.
  void recordGeneration(VkCommandBuffer cmd, const ComputeProgram& generator,
                        VkDescriptorSet generatorSet, const ComputeProgram& mip,
                        VkDescriptorSet mipSet, std::uint32_t seed);

  const OwnedImage& image() const { return image_; }
  VkDeviceSize bytes() const { return image_.bytes(); }

 private:
  const DeviceContext* device_;
  OwnedImage image_;
};

}  // namespace clouds::detail
