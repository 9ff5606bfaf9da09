// A weather region's place (FrameInputs::weatherRegions, cloud_weather_regions.h): where its
// core lies and how strongly it holds at a distance from it. The regions' look and the
// superstorm's turn (cloud_vortex.h) both weigh a point by these.
#ifndef CLOUDS_CLOUD_REGION_SHAPE_H
#define CLOUDS_CLOUD_REGION_SHAPE_H

#include "cloud_types.h"

FX_SHADER_BEGIN(clouds::shader)

// Region `index` (< u.weatherRegionCount) of the frame's: the C++ struct's member; the
// shaders' frame block's, read in place (frame_uniforms.glsl; cloud_types.h says why).
// The regions a frame may have (Settings::weatherRegions): the shaders' specialization
// constant, so that the loops over them (cloud_weather_regions.h) unroll over constant indices
// and a pipeline without regions has no region code (a loop over the uniform count, even of no
// trips, doubled the march's time on lavapipe).
#ifdef __cplusplus
FX_INLINE WeatherRegionUniform weatherRegion(IN(CloudUniforms) u, uint index) {
  return u.weatherRegions[index];
}
FX_INLINE uint weatherRegionCapacity() {
  return kMaxWeatherRegions;
}
#else
WeatherRegionUniform weatherRegion(IN(CloudUniforms) u, uint index);
uint weatherRegionCapacity();
#endif

// Distance (m) from a camera-relative point (x, z) to a region's core rectangle; 0 inside.
FX_INLINE float regionCoreDistance(vec2 relative, IN(WeatherRegionUniform) r) {
  const vec2 d = relative - vec2(r.placement.x, r.placement.y);
  const vec2 local = vec2(dot(d, vec2(r.shape.x, r.shape.y)), dot(d, vec2(-r.shape.y, r.shape.x)));
  return length(max(abs(local) - vec2(r.placement.z, r.placement.w), vec2(0.0f)));
}

// A region's strength at a distance from its core: 1 within the rounding radius, eased to 0
// over the blend distance.
FX_INLINE float regionStrength(float coreDistance, IN(WeatherRegionUniform) r) {
  return 1.0f - smoothstep(r.shape.z, r.shape.z + r.shape.w, coreDistance);
}

FX_SHADER_END

#endif
