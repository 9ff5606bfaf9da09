// proceduralWeatherAt(): the procedural weather map's function (cloud_weather.h, the same code
// the generator shader runs) decoded as the march decodes a texel (cloud_density.h).
#include <cmath>

#include "cloud_density.h"
#include "cloud_weather.h"
#include "clouds/clouds.h"
#include "uniforms.h"

namespace clouds {

WeatherColumn proceduralWeatherAt(const Settings& settings, std::uint32_t noiseSeed,
                                  glm::dvec2 xzMetres, double timeSeconds) {
  const double tile = settings.weatherTileMetres;
  const glm::vec2 uv(float(detail::wrapToTile(xzMetres.x, tile) / tile),
                     float(detail::wrapToTile(xzMetres.y, tile) / tile));
  // A map is the weather at the start of its update period (record_weather.cpp).
  const double period = settings.weatherUpdateSeconds;
  const double mapTime = period > 0.0 ? std::floor(timeSeconds / period) * period : timeSeconds;
  const double phase = mapTime * settings.weatherEvolutionPerSecond;
  const glm::vec4 texel =
      shader::proceduralWeatherTexel(uv, float(phase - std::floor(phase)), noiseSeed);
  shader::CloudUniforms u{};
  u.coverage = settings.coverage;
  u.cloudType = settings.cloudType;
  u.typeVariation = settings.typeVariation;
  u.densityVariation = settings.densityVariation;
  const shader::WeatherSample w = shader::decodeWeather(texel, u);
  return {w.coverage, w.type, w.density};
}

}  // namespace clouds
