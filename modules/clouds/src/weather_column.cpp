// proceduralWeatherAt(): the procedural weather map's function (cloud_weather.h, the same code
// the generator shader runs) decoded as the march decodes a texel (cloud_density.h).
#include "cloud_weather.h"
#include "clouds/clouds.h"
#include "clouds/procedural_textures.h"
#include "uniforms.h"

namespace clouds {

WeatherColumn proceduralWeatherAt(const Settings& settings, std::uint32_t noiseSeed,
                                  glm::dvec2 xzMetres, double timeSeconds) {
  const double tile = settings.weatherTileMetres;
  const glm::vec2 uv(float(detail::wrapToTile(xzMetres.x, tile) / tile),
                     float(detail::wrapToTile(xzMetres.y, tile) / tile));
  const glm::vec4 texel =
      shader::proceduralWeatherTexel(uv, proceduralWeatherPhase(settings, timeSeconds), noiseSeed);
  const glm::vec4 w = weatherAsMarched(texel, settings);
  return {w.x, w.y, w.z};
}

}  // namespace clouds
