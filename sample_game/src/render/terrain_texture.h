#pragma once
// A user terrain's base colour texture (its glTF's material 0) on the GPU: sRGB texels with a
// mip chain made at load, and sampled with repeat and trilinear filtering, so a texture stretched
// over kilometres neither aliases in the distance nor shimmers as the pilot flies. A mesh without
// one gets a one-texel white stand-in (the terrain's pipeline then reads nothing from it: its
// kTextured constant is off).
#include <cstdint>
#include <vector>

#include "engine/assets/image_io.h"
#include "engine/gfx/resources.h"

namespace sample {

// Every mip of an sRGB RGBA8 image, each level's sides halved (rounded down, at least 1) and its
// texels the mean of the 2x2 texels below it (the last row or column repeated where a side is
// odd), averaged in linear light: a black and white checker becomes the grey that reflects half
// the light (sRGB 188), not sRGB 128. Alpha is averaged as it is.
struct MipChain {
  std::uint32_t width = 0, height = 0, levels = 0;
  std::vector<std::uint8_t> texels;  // level 0, then 1, ..., tightly packed RGBA8
};
MipChain srgbMipChain(const engine::assets::ImageRgba8& image);

class TerrainTexture {
 public:
  // `image` empty: the one-texel white stand-in. Throws engine::Error when the upload fails.
  TerrainTexture(engine::gfx::Device& device, const engine::assets::ImageRgba8& image);
  bool present() const { return present_; }
  VkImageView view() const { return image_.view(); }
  VkSampler sampler() const { return sampler_.vk(); }
  static constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_SRGB;

 private:
  bool present_ = false;
  engine::gfx::Image image_;
  engine::gfx::Sampler sampler_;
};

}  // namespace sample
