#pragma once
// Reading CPU images as the GPU's samplers clamped to the edge read them, for the harness's
// stand-ins of the shaders' fetches: a row-major width x height image of texels of type T
// (float, glm::vec4). Coordinates are [0, 1] per axis over the whole image.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace clouds::tools {

// The texels a linear filter at `uv` blends: the lower-left one's index, and the weights.
struct Footprint {
  int x = 0;
  int y = 0;
  glm::vec2 weight{0.0f};
};

inline Footprint footprintAt(glm::vec2 uv, std::uint32_t width, std::uint32_t height) {
  const glm::vec2 p = uv * glm::vec2(width, height) - 0.5f;
  const glm::vec2 base = glm::floor(p);
  return {int(base.x), int(base.y), p - base};
}

template <class T>
const T& clampedTexel(const std::vector<T>& texels, std::uint32_t width, std::uint32_t height,
                      int x, int y) {
  const int cx = std::clamp(x, 0, int(width) - 1);
  const int cy = std::clamp(y, 0, int(height) - 1);
  return texels[std::size_t(cy) * width + std::size_t(cx)];
}

// textureLod with a linear, clamped sampler.
template <class T>
T sampleLinearClamped(const std::vector<T>& texels, std::uint32_t width, std::uint32_t height,
                      glm::vec2 uv) {
  const Footprint f = footprintAt(uv, width, height);
  const auto at = [&](int x, int y) { return clampedTexel(texels, width, height, x, y); };
  return glm::mix(glm::mix(at(f.x, f.y), at(f.x + 1, f.y), f.weight.x),
                  glm::mix(at(f.x, f.y + 1), at(f.x + 1, f.y + 1), f.weight.x), f.weight.y);
}

}  // namespace clouds::tools
