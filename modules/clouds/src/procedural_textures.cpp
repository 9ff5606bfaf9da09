// The procedural textures on the CPU: each function evaluates the texel function its generator
// shader evaluates (noise_shape.comp, noise_detail.comp, hero_noise.comp, noise_curl.comp,
// weather_procedural.comp) at the same texel centres.
#include "clouds/procedural_textures.h"

#include <cmath>

#include "cloud_density.h"
#include "cloud_noise.h"
#include "cloud_types.h"
#include "cloud_weather.h"

namespace clouds {

static_assert(kShapeNoiseTexels == shader::kShapeNoiseSize);
static_assert(kDetailNoiseTexels == shader::kDetailNoiseSize);
static_assert(kHeroNoiseTexels == shader::kHeroNoiseSize);
static_assert(kCurlNoiseTexels == shader::kCurlNoiseSize);
static_assert(kWeatherMapTexels == shader::kWeatherMapSize);

namespace {

// The size x size slice `z` of a volume whose texel at uvw holds `texel(uvw)`.
template <typename Value, typename Texel>
std::vector<Value> volumeSlice(int size, int z, Texel texel) {
  std::vector<Value> slice(std::size_t(size) * std::size_t(size));
  const float inverse = 1.0f / float(size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const glm::vec3 uvw = (glm::vec3(float(x), float(y), float(z)) + 0.5f) * inverse;
      slice[std::size_t(y) * std::size_t(size) + std::size_t(x)] = texel(uvw);
    }
  }
  return slice;
}

// The size x size map whose texel at uv holds `texel(uv)`.
template <typename Value, typename Texel>
std::vector<Value> mapOf(int size, Texel texel) {
  std::vector<Value> map(std::size_t(size) * std::size_t(size));
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const glm::vec2 uv = (glm::vec2(float(x), float(y)) + 0.5f) / float(size);
      map[std::size_t(y) * std::size_t(size) + std::size_t(x)] = texel(uv);
    }
  }
  return map;
}

}  // namespace

std::vector<float> shapeNoiseSlice(std::uint32_t noiseSeed, int z) {
  return volumeSlice<float>(kShapeNoiseTexels, z, [&](glm::vec3 uvw) {
    return shader::shapeNoiseValue(shader::lowFrequencyNoiseTexel(uvw, noiseSeed));
  });
}

std::vector<float> detailNoiseSlice(std::uint32_t noiseSeed, int z) {
  return volumeSlice<float>(kDetailNoiseTexels, z, [&](glm::vec3 uvw) {
    return shader::detailNoiseValue(shader::highFrequencyNoiseTexel(uvw, noiseSeed));
  });
}

std::vector<glm::vec4> heroNoiseSlice(std::uint32_t noiseSeed, int z) {
  return volumeSlice<glm::vec4>(
      kHeroNoiseTexels, z, [&](glm::vec3 uvw) { return shader::heroNoiseTexel(uvw, noiseSeed); });
}

std::vector<glm::vec2> curlNoise(std::uint32_t noiseSeed) {
  return mapOf<glm::vec2>(kCurlNoiseTexels, [&](glm::vec2 uv) {
    return shader::curlNoiseTexel(uv, 1.0f / float(kCurlNoiseTexels), noiseSeed);
  });
}

float proceduralWeatherPhase(const Settings& settings, double timeSeconds) {
  const double period = settings.weatherUpdateSeconds;
  const double mapTime = period > 0.0 ? std::floor(timeSeconds / period) * period : timeSeconds;
  const double phase = mapTime * settings.weatherEvolutionPerSecond;
  return float(phase - std::floor(phase));
}

std::vector<glm::vec4> proceduralWeatherMap(std::uint32_t noiseSeed, float phase) {
  return mapOf<glm::vec4>(kWeatherMapTexels, [&](glm::vec2 uv) {
    return shader::proceduralWeatherTexel(uv, phase, noiseSeed);
  });
}

std::uint8_t storedUnorm8(float value) {
  const float clamped = value > 1.0f ? 1.0f : (value > 0.0f ? value : 0.0f);  // NaN -> 0
  return static_cast<std::uint8_t>(std::lround(clamped * 255.0f));
}

}  // namespace clouds
