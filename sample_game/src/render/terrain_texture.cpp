#include "render/terrain_texture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "engine/gfx/upload.h"
#include "tonemap_operator.h"

namespace sample {

using namespace engine;

namespace {

float srgbToLinear(std::uint8_t value) {
  const float c = float(value) / 255.0f;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// The engine's sRGB encoding (the tonemapper's), to 8 bits.
std::uint8_t linearToSrgb8(float linear) {
  const float s = shaders::linearToSrgb(std::clamp(linear, 0.0f, 1.0f));
  return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

}  // namespace

MipChain srgbMipChain(const assets::ImageRgba8& image) {
  MipChain chain{image.width, image.height, 1, image.pixels};
  if (image.width == 0 || image.height == 0) return {};
  std::array<float, 256> linear{};
  for (std::size_t v = 0; v < linear.size(); ++v) linear[v] = srgbToLinear(std::uint8_t(v));
  std::uint32_t w = image.width, h = image.height;
  std::size_t level = 0;  // where the level below starts in `texels`
  while (w > 1 || h > 1) {
    const std::uint32_t nw = std::max(w / 2, 1u), nh = std::max(h / 2, 1u);
    const std::size_t next = chain.texels.size();
    chain.texels.resize(next + std::size_t(4) * nw * nh);
    for (std::uint32_t y = 0; y < nh; ++y) {
      for (std::uint32_t x = 0; x < nw; ++x) {
        std::array<float, 4> sum{};
        for (std::uint32_t dy = 0; dy < 2; ++dy) {
          for (std::uint32_t dx = 0; dx < 2; ++dx) {
            const std::uint32_t sx = std::min(2 * x + dx, w - 1), sy = std::min(2 * y + dy, h - 1);
            const std::uint8_t* t = &chain.texels[level + 4 * (std::size_t(sy) * w + sx)];
            for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += linear[t[c]];
            sum[3] += float(t[3]) / 255.0f;
          }
        }
        std::uint8_t* out = &chain.texels[next + 4 * (std::size_t(y) * nw + x)];
        for (int c = 0; c < 3; ++c) out[c] = linearToSrgb8(sum[std::size_t(c)] / 4.0f);
        out[3] = static_cast<std::uint8_t>(std::lround(sum[3] / 4.0f * 255.0f));
      }
    }
    level = next;
    w = nw;
    h = nh;
    ++chain.levels;
  }
  return chain;
}

TerrainTexture::TerrainTexture(gfx::Device& device, const assets::ImageRgba8& image)
    : present_(image.width > 0 && image.height > 0) {
  const assets::ImageRgba8 white{1, 1, {255, 255, 255, 255}};
  const MipChain chain = srgbMipChain(present_ ? image : white);
  image_ = gfx::Image(device,
                      gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                     kFormat,
                                     {chain.width, chain.height, 1},
                                     chain.levels,
                                     1,
                                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     "terrain base colour"});
  gfx::uploadMipsToImage(device, image_, std::as_bytes(std::span(chain.texels)), chain.levels,
                         gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                         VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  gfx::SamplerDesc repeat;
  repeat.addressMode = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  repeat.debugName = "terrain base colour trilinear";
  sampler_ = gfx::Sampler(device, repeat);
}

}  // namespace sample
