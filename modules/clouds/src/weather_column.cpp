// A weather texel as the march decodes it (cloud_density.h) under the column's weather regions
// (cloud_weather_regions.h): proceduralWeatherAt() (the procedural map's function,
// cloud_weather.h, the same code the generator shader runs) and weatherAsMarched().
#include "cloud_density.h"
#include "cloud_weather.h"
#include "clouds/clouds.h"
#include "clouds/procedural_textures.h"
#include "uniforms.h"
#include "weather_regions.h"

namespace clouds {
namespace detail {

WeatherColumn marchedColumn(glm::vec4 texel, const Settings& settings,
                            std::span<const WeatherRegion> regions, glm::dvec2 xzMetres,
                            double seconds) {
  // The regions about the column itself, which then lies at the uniforms' origin.
  FrameInputs at;
  at.cameraPosition = glm::dvec3(xzMetres.x, 0.0, xzMetres.y);
  at.weatherRegions = regions;
  at.timeSeconds = seconds;
  shader::CloudUniforms u{};
  u.coverage = settings.coverage;
  u.cloudType = settings.cloudType;
  u.typeVariation = settings.typeVariation;
  u.densityVariation = settings.densityVariation;
  u.anvilBias = settings.anvilBias;
  setWeatherRegions(u, at, settings);
  shader::ColumnWeather column = shader::columnWeather(glm::vec2(0.0f), u);
  if (u.vortexRegion != shader::kNoVortex) {
    // A superstorm's look where its turn brought the column from, each flow phase's, mixed by
    // their weights (the march mixes the two phases' fields: layerField()).
    const shader::WeatherRegionUniform& storm = u.weatherRegions[u.vortexRegion];
    const shader::ColumnWeather a =
        shader::columnWeather(shader::vortexTurnedBack(glm::vec2(0.0f), u.vortexClock.x, storm), u);
    const shader::ColumnWeather b =
        shader::columnWeather(shader::vortexTurnedBack(glm::vec2(0.0f), u.vortexClock.y, storm), u);
    const float w = u.vortexClock.z;
    column.coverage = glm::mix(b.coverage, a.coverage, w);
    column.cloudType = glm::mix(b.cloudType, a.cloudType, w);
    column.densityScale = glm::mix(b.densityScale, a.densityScale, w);
    column.anvilBias = glm::mix(b.anvilBias, a.anvilBias, w);
  }
  // The map's density alone (the column's scale of the densest multiplier kept apart).
  shader::ColumnWeather unscaled = column;
  unscaled.densityScale = 1.0f;
  const shader::WeatherSample w = shader::decodeWeather(texel, unscaled, u);
  return {w.coverage, w.type, w.density,
          column.densityScale * densestMultiplier(settings, regions)};
}

}  // namespace detail

WeatherColumn proceduralWeatherAt(const Settings& settings, std::uint32_t noiseSeed,
                                  glm::dvec2 xzMetres, double timeSeconds,
                                  std::span<const WeatherRegion> regions) {
  const double tile = settings.weatherTileMetres;
  const glm::vec2 uv(float(detail::wrapToTile(xzMetres.x, tile) / tile),
                     float(detail::wrapToTile(xzMetres.y, tile) / tile));
  const glm::vec4 texel =
      shader::proceduralWeatherTexel(uv, proceduralWeatherPhase(settings, timeSeconds), noiseSeed);
  return detail::marchedColumn(texel, settings, regions, xzMetres, timeSeconds);
}

glm::vec4 weatherAsMarched(glm::vec4 texel, const Settings& settings,
                           std::span<const WeatherRegion> regions, glm::dvec2 xzMetres) {
  const WeatherColumn c = detail::marchedColumn(texel, settings, regions, xzMetres, 0.0);
  return {c.coverage, c.type, c.density, 1.0f};
}

}  // namespace clouds
