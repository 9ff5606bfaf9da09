// The empty-space-skipping grid over the weather map (weather_max.comp builds it on the GPU;
// the CPU reference builds its copy with the same function): each cell holds the maximum
// coverage (x) and cloud type (y) of the `cellSize` x `cellSize` source texels it covers plus
// a one-texel apron, because the march filters the weather map bilinearly and a neighbouring
// texel can leak into the cell. Coordinates wrap: the weather map tiles.
#ifndef CLOUDS_CLOUD_WEATHER_MAXIMA_H
#define CLOUDS_CLOUD_WEATHER_MAXIMA_H

#include "cloud_types.h"

FX_SHADER_BEGIN(clouds::shader)

// Prototype: the source level's texel (already wrapped into [0, sourceSize)).
vec4 fetchMaximaSource(ivec2 texel);

FX_INLINE vec2 weatherCellMaxima(ivec2 cell, int sourceSize, int cellSize) {
  vec2 maxima = vec2(0.0f);
  for (int y = -1; y <= cellSize; ++y) {
    for (int x = -1; x <= cellSize; ++x) {
      const ivec2 texel = (cell * cellSize + ivec2(x, y) + sourceSize) % sourceSize;
      const vec4 source = fetchMaximaSource(texel);
      maxima = max(maxima, vec2(source.x, source.y));
    }
  }
  return maxima;
}

FX_SHADER_END

#endif
