// A user terrain's base colour texture on the GPU (sample_game/src/render/terrain_texture.h):
// its mip chain, averaged in linear light.
#include <gtest/gtest.h>

#include "render/terrain_texture.h"

namespace {

using engine::assets::ImageRgba8;

ImageRgba8 filled(std::uint32_t width, std::uint32_t height, std::uint8_t value) {
  ImageRgba8 image{width, height, std::vector<std::uint8_t>(std::size_t(4) * width * height)};
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    image.pixels[i] = i % 4 == 3 ? 255 : value;
  }
  return image;
}

TEST(TerrainTexture, TheMipChainHalvesEachSideDownToOneTexel) {
  const sample::MipChain chain = sample::srgbMipChain(filled(5, 3, 100));
  EXPECT_EQ(chain.levels, 3u) << "5x3, 2x1, 1x1";
  EXPECT_EQ(chain.texels.size(), 4u * (5 * 3 + 2 * 1 + 1));
  // A uniform image stays uniform at every level, alpha included.
  for (std::size_t i = 0; i < chain.texels.size(); ++i) {
    EXPECT_EQ(chain.texels[i], i % 4 == 3 ? 255 : 100) << "byte " << i;
  }
  EXPECT_EQ(sample::srgbMipChain(filled(1, 1, 7)).levels, 1u);
  EXPECT_EQ(sample::srgbMipChain(filled(256, 64, 7)).levels, 9u);
  EXPECT_EQ(sample::srgbMipChain(ImageRgba8{}).levels, 0u);
}

// A black and white checker averages to the grey that reflects half the light: sRGB 188, not
// the 128 an average of the stored values would give (a far textured slope would darken).
TEST(TerrainTexture, MipsAverageInLinearLight) {
  ImageRgba8 checker = filled(2, 2, 0);
  for (const std::size_t texel : {0u, 3u}) {
    for (std::size_t c = 0; c < 3; ++c) checker.pixels[4 * texel + c] = 255;
  }
  const sample::MipChain chain = sample::srgbMipChain(checker);
  ASSERT_EQ(chain.levels, 2u);
  const std::uint8_t* top = &chain.texels[4 * 4];
  EXPECT_EQ(top[0], 188);
  EXPECT_EQ(top[1], 188);
  EXPECT_EQ(top[2], 188);
  EXPECT_EQ(top[3], 255);
}

}  // namespace
