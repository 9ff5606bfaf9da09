#pragma once
// The module's procedural textures computed on the CPU, with the very functions its generator
// shaders run (shaders/cloud_noise.h, cloud_weather.h compiled as C++): for artists who want to
// inspect them or paint over them (tools/clouds/generator: clouds_textures writes them as PNG and
// EXR), and for hosts that bake. Values are what a generator shader computes before its image
// stores them as 8 bits; storedUnorm8() gives the stored byte. A painted weather map made from
// proceduralWeatherMap() (FrameInputs::weatherView) shows the procedural clouds of that moment.
//
// Plain CPU code: no Vulkan, no threads. Each call makes one slice or one map, so a caller can
// spread a volume over its own threads.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "clouds/clouds.h"

namespace clouds {

// Texels per side of each texture (the module's own sizes, cloud_types.h).
inline constexpr int kShapeNoiseTexels = 128;  // low-frequency shape, a scalar volume
inline constexpr int kDetailNoiseTexels = 32;  // high-frequency detail, a scalar volume
inline constexpr int kHeroNoiseTexels = 128;   // hero clouds' detail, four channels
inline constexpr int kCurlNoiseTexels = 128;   // 2D curl, two channels
inline constexpr int kWeatherMapTexels = 512;  // 2D weather map: coverage, type, density

// Slice `z` of a noise volume (texel centres at (i + 0.5) / size), x fastest: size^2 values.
std::vector<float> shapeNoiseSlice(std::uint32_t noiseSeed, int z);
std::vector<float> detailNoiseSlice(std::uint32_t noiseSeed, int z);
// R, G the curly alligator (wisps), B, A the alligator (billows), low then high frequency.
std::vector<glm::vec4> heroNoiseSlice(std::uint32_t noiseSeed, int z);
// The curl noise, encoded as 0.5 + 0.5 x curl (the module's RG), x fastest.
std::vector<glm::vec2> curlNoise(std::uint32_t noiseSeed);

// The evolution phase, in [0, 1), of the procedural weather map the module shows at
// `timeSeconds` under `settings` (a map is the weather at the start of its update period).
float proceduralWeatherPhase(const Settings& settings, double timeSeconds);
// The procedural weather map at `phase` (R coverage, G type, B density, A 1), x fastest, row 0
// at v = 0 (world z = 0 of the tile): the map as the module generates it.
std::vector<glm::vec4> proceduralWeatherMap(std::uint32_t noiseSeed, float phase);
// A weather texel as the march reads it under `settings` (the weather state's coverage, type
// and density applied) and the regions over its world column `xzMetres`: R coverage, G type,
// B the map's density (the column's multiplier aside: WeatherColumn), A 1, each in [0, 1].
glm::vec4 weatherAsMarched(glm::vec4 texel, const Settings& settings,
                           std::span<const WeatherRegion> regions = {}, glm::dvec2 xzMetres = {});

// The byte an RGBA8 UNORM image stores for `value` (clamped to [0, 1], rounded to nearest).
std::uint8_t storedUnorm8(float value);

}  // namespace clouds
