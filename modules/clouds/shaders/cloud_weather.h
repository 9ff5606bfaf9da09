// The procedural weather map (Schneider 2017: "octaves of noise" in the cloud map; the
// Stingray log: 5 octaves of animated Perlin noise): R coverage, G cloud type, B density.
// Each channel is periodic Perlin fBm over the tile, evolving along a third, periodic axis so
// the map changes slowly without sliding (the wind scrolls the noise, not the coverage).
#ifndef CLOUDS_CLOUD_WEATHER_H
#define CLOUDS_CLOUD_WEATHER_H

#include "cloud_noise.h"

FX_SHADER_BEGIN(clouds::shader)

// `uv` in [0, 1) over the tile; `phase` in [0, 1) the evolution of the weather.
FX_INLINE vec4 proceduralWeatherTexel(vec2 uv, float phase, uint seed) {
  const float coverage = perlinFbm(vec3(uv.x, uv.y, phase), 4, 5, seed + 100u);
  const float type = perlinFbm(vec3(uv.x, uv.y, phase), 2, 2, seed + 200u);
  const float density = perlinFbm(vec3(uv.x, uv.y, phase), 4, 3, seed + 300u);
  // Stretch the fBm's narrow middle range over [0, 1] so coverage 0.5 gives broken skies.
  return vec4(saturate(remap(coverage, 0.3f, 0.7f, 0.0f, 1.0f)),
              saturate(remap(type, 0.3f, 0.7f, 0.0f, 1.0f)),
              saturate(remap(density, 0.3f, 0.7f, 0.2f, 1.0f)), 1.0f);
}

FX_SHADER_END

#endif
