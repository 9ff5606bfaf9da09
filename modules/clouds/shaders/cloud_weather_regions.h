// Weather regions (Schneider 2022's regional influence; Schneider 2017's zones with weather of
// their own): places on the ground whose look (coverage, cloud type, density, anvils) differs
// from the surrounding weather's, blended into it over a distance, so a storm front can stand
// over the mountains while the plains stay fair and a pilot flies from one into the other.
//
// A region is a rectangle (of any size, none for a disc) grown by a rounding radius: its look
// at full strength within that, eased (smoothstep) into what lies around it over its blend
// distance beyond. Regions apply in order, each mixing its look into what the surrounding
// weather and the regions before it made. The march reads a column's weather here
// (columnWeather()); empty-space skipping bounds it over a cell (columnWeatherCeiling()).
#ifndef CLOUDS_CLOUD_WEATHER_REGIONS_H
#define CLOUDS_CLOUD_WEATHER_REGIONS_H

#include "cloud_vortex.h"

FX_SHADER_BEGIN(clouds::shader)

// The look of the weather over one column of the layer (Settings' meanings).
struct ColumnWeather {
  float coverage;
  float cloudType;
  float densityScale;  // times u.extinctionPerMetre
  float anvilBias;
};

FX_INLINE ColumnWeather surroundingWeather(IN(CloudUniforms) u) {
  ColumnWeather c;
  c.coverage = u.coverage;
  c.cloudType = u.cloudType;
  c.densityScale = u.layerDensityScale;
  c.anvilBias = u.anvilBias;
  return c;
}

// The weather over the column at a camera-relative point (x, z m).
FX_INLINE ColumnWeather columnWeather(vec2 relative, IN(CloudUniforms) u) {
  ColumnWeather c = surroundingWeather(u);
  for (uint i = 0u; i < weatherRegionCapacity(); ++i) {
    if (i >= u.weatherRegionCount) break;
    const WeatherRegionUniform region = weatherRegion(u, i);
    const float strength = regionStrength(regionCoreDistance(relative, region), region);
    vec4 look = region.look;
    if (hasVortex(u) && i == u.vortexRegion) {
      const vec2 storm = vortexLook(relative, region, vec2(look.x, look.y));
      look.x = storm.x;
      look.y = storm.y;
    }
    c.coverage = mix(c.coverage, look.x, strength);
    c.cloudType = mix(c.cloudType, look.y, strength);
    c.densityScale = mix(c.densityScale, look.z, strength);
    c.anvilBias = mix(c.anvilBias, look.w, strength);
  }
  return c;
}

// The largest coverage (x) and cloud type (y) of any column within `radius` metres of the
// camera-relative point: an upper bound, so a cell it calls empty is. (The core distance moves
// no faster than the point, so over the disc each strength lies between its values at the
// distance +- radius; mix(c, look, s) grows with c and is linear in s, so its largest value is
// at the largest c and one end of s's range.)
FX_INLINE vec2 columnWeatherCeiling(vec2 relative, float radius, IN(CloudUniforms) u) {
  vec2 ceiling = vec2(u.coverage, u.cloudType);
  for (uint i = 0u; i < weatherRegionCapacity(); ++i) {
    if (i >= u.weatherRegionCount) break;
    const WeatherRegionUniform region = weatherRegion(u, i);
    const float distance = regionCoreDistance(relative, region);
    const float strongest = regionStrength(max(distance - radius, 0.0f), region);
    const float weakest = regionStrength(distance + radius, region);
    // A superstorm's wall is full cumulonimbus (vortexLook()).
    const vec2 look =
        hasVortex(u) && i == u.vortexRegion ? vec2(1.0f) : vec2(region.look.x, region.look.y);
    ceiling = max(mix(ceiling, look, strongest), mix(ceiling, look, weakest));
  }
  return ceiling;
}

FX_SHADER_END

#endif
