// The Nubis vertical-profile density model (Schneider 2015/2017, Schneider 2022): a weather
// map gives coverage, cloud type and a density scale; type picks a height gradient; coverage
// erodes the low-frequency Perlin-Worley/Worley shape by a remap (an anvil bias inflates it
// near the top); high-frequency Worley noise erodes the edges, wispy at the base and billowy at
// the top. All inputs are plain values so GPU and CPU evaluate the same function.
#ifndef CLOUDS_CLOUD_DENSITY_H
#define CLOUDS_CLOUD_DENSITY_H

#include "cloud_math.h"
#include "cloud_types.h"
#include "cloud_weather_regions.h"

FX_SHADER_BEGIN(clouds::shader)

struct WeatherSample {
  float coverage;  // [0, 1]: fraction of the sky this column can fill
  float type;      // 0 stratus, 0.5 stratocumulus, 1 cumulus
  float density;   // density scale (wetness, [0, 1]) times the column's (ColumnWeather)
  float anvilBias;
};

// Height-gradient ramps (up start, up end, down start, down end) as fractions of the layer.
FX_INLINE vec4 typeProfile(float type) {
  const vec4 stratus = vec4(0.0f, 0.06f, 0.16f, 0.28f);
  const vec4 stratocumulus = vec4(0.02f, 0.16f, 0.42f, 0.62f);
  const vec4 cumulus = vec4(0.0f, 0.12f, 0.72f, 1.0f);
  const float t = saturate(type);
  return t < 0.5f ? mix(stratus, stratocumulus, t * 2.0f)
                  : mix(stratocumulus, cumulus, t * 2.0f - 1.0f);
}

// Probability of cloud at `heightFraction` (0 = layer bottom, 1 = top) for a cloud type.
FX_INLINE float heightGradient(float heightFraction, float type) {
  const vec4 r = typeProfile(type);
  return remapClamped(heightFraction, r.x, r.y, 0.0f, 1.0f) *
         remapClamped(heightFraction, r.z, r.w, 1.0f, 0.0f);
}

// The coverage of a weather texel under the global coverage c: texel + 2 c - 1, so c = 0 is a
// clear sky, c = 1 overcast and 0.5 the map as painted. (The host side uses it too, to know a
// sky that cannot hold cloud.)
FX_INLINE float layerCoverage(float weatherCoverage, float coverage) {
  return saturate(weatherCoverage + 2.0f * coverage - 1.0f);
}

// Decodes an RGBA8 weather texel under its column's weather: coverage by layerCoverage(), type
// = the column's type moved by the map's variation, density = mix(1, texel density, variation)
// times the column's scale.
FX_INLINE WeatherSample decodeWeather(vec4 texel, IN(ColumnWeather) column, IN(CloudUniforms) u) {
  WeatherSample w;
  w.coverage = layerCoverage(texel.x, column.coverage);
  w.type = saturate(column.cloudType + (texel.y - 0.5f) * u.typeVariation);
  w.density = mix(1.0f, saturate(texel.z), saturate(u.densityVariation)) * column.densityScale;
  w.anvilBias = column.anvilBias;
  return w;
}

// The low-frequency shape of the clouds (the "cheap" sample).
struct CoarseShape {
  float profile;  // [0, 1]: 0 at a cloud's edge, 1 in its core (the role of Nubis 2022's
                  //   dimensional profile; the in-scatter probability reads it)
  float density;  // [0, 1]: the profile scaled by the coverage
};

// `shapeNoise`: the shape noise's value (shapeNoiseValue()).
FX_INLINE CoarseShape coarseShape(float shapeNoise, float heightFraction, IN(WeatherSample) w) {
  CoarseShape shape;
  shape.profile = 0.0f;
  shape.density = 0.0f;
  if (heightFraction < 0.0f || heightFraction > 1.0f) return shape;
  float base = shapeNoise;
  base *= heightGradient(heightFraction, w.type);
  // Anvil: raise coverage towards the top of the layer.
  const float anvilExponent =
      remapClamped(heightFraction, 0.7f, 0.8f, 1.0f, mix(1.0f, 0.5f, saturate(w.anvilBias)));
  const float coverage = pow(saturate(w.coverage), anvilExponent);
  // Coverage as erosion: only noise above (1 - coverage) survives, rescaled.
  shape.profile = saturate(remap(base, 1.0f - coverage, 1.0f, 0.0f, 1.0f));
  shape.density = shape.profile * coverage;
  return shape;
}

// Erodes a base density by the high-frequency detail noise (detailNoiseValue(): wispy low,
// billowy high).
FX_INLINE float erodeDensity(float base, float detailNoise, float heightFraction, float erosion) {
  const float modifier = mix(detailNoise, 1.0f - detailNoise, saturate(heightFraction * 10.0f));
  return saturate(remap(base, modifier * erosion, 1.0f, 0.0f, 1.0f));
}

FX_SHADER_END

#endif
