// Texture sampling for the cloud model, shared by GPU and CPU. Shaders implement the fetch
// prototypes with texelFetch on RGBA8 textures; the CPU reference with array lookups of the
// same (read-back) texels. Filtering is done here, by hand: trilinear from 8 fetches is about
// twice as fast as sampler filtering of 3D textures on lavapipe, and it makes GPU and CPU
// filter identically. Coordinates are in tile units and wrap (the textures tile).
#ifndef CLOUDS_CLOUD_SAMPLING_H
#define CLOUDS_CLOUD_SAMPLING_H

#include "cloud_types.h"

VKFX_SHADER_BEGIN(clouds::shader)

// Prototypes: texel coordinates are already wrapped into the texture.
vec4 fetchShapeNoise(ivec3 texel);
vec4 fetchDetailNoise(ivec3 texel);
vec4 fetchWeather(ivec2 texel);
vec4 fetchCurl(ivec2 texel);
vec4 fetchWeatherMaxFine(ivec2 texel);    // kWeatherMaxFineSize^2
vec4 fetchWeatherMaxCoarse(ivec2 texel);  // kWeatherMaxCoarseSize^2

VKFX_INLINE vec4 sampleShapeNoise(vec3 uvw) {
  const int mask = kShapeNoiseSize - 1;
  const vec3 p = uvw * float(kShapeNoiseSize) - 0.5f;
  const vec3 pFloor = floor(p);
  const vec3 f = p - pFloor;
  const ivec3 i0 = ivec3(pFloor) & mask;
  const ivec3 i1 = (i0 + 1) & mask;
  const vec4 c000 = fetchShapeNoise(ivec3(i0.x, i0.y, i0.z));
  const vec4 c100 = fetchShapeNoise(ivec3(i1.x, i0.y, i0.z));
  const vec4 c010 = fetchShapeNoise(ivec3(i0.x, i1.y, i0.z));
  const vec4 c110 = fetchShapeNoise(ivec3(i1.x, i1.y, i0.z));
  const vec4 c001 = fetchShapeNoise(ivec3(i0.x, i0.y, i1.z));
  const vec4 c101 = fetchShapeNoise(ivec3(i1.x, i0.y, i1.z));
  const vec4 c011 = fetchShapeNoise(ivec3(i0.x, i1.y, i1.z));
  const vec4 c111 = fetchShapeNoise(ivec3(i1.x, i1.y, i1.z));
  return mix(mix(mix(c000, c100, f.x), mix(c010, c110, f.x), f.y),
             mix(mix(c001, c101, f.x), mix(c011, c111, f.x), f.y), f.z);
}

VKFX_INLINE vec4 sampleDetailNoise(vec3 uvw) {
  const int mask = kDetailNoiseSize - 1;
  const vec3 p = uvw * float(kDetailNoiseSize) - 0.5f;
  const vec3 pFloor = floor(p);
  const vec3 f = p - pFloor;
  const ivec3 i0 = ivec3(pFloor) & mask;
  const ivec3 i1 = (i0 + 1) & mask;
  const vec4 c000 = fetchDetailNoise(ivec3(i0.x, i0.y, i0.z));
  const vec4 c100 = fetchDetailNoise(ivec3(i1.x, i0.y, i0.z));
  const vec4 c010 = fetchDetailNoise(ivec3(i0.x, i1.y, i0.z));
  const vec4 c110 = fetchDetailNoise(ivec3(i1.x, i1.y, i0.z));
  const vec4 c001 = fetchDetailNoise(ivec3(i0.x, i0.y, i1.z));
  const vec4 c101 = fetchDetailNoise(ivec3(i1.x, i0.y, i1.z));
  const vec4 c011 = fetchDetailNoise(ivec3(i0.x, i1.y, i1.z));
  const vec4 c111 = fetchDetailNoise(ivec3(i1.x, i1.y, i1.z));
  return mix(mix(mix(c000, c100, f.x), mix(c010, c110, f.x), f.y),
             mix(mix(c001, c101, f.x), mix(c011, c111, f.x), f.y), f.z);
}

VKFX_INLINE vec4 sampleWeather(vec2 uv) {
  const int mask = kWeatherMapSize - 1;
  const vec2 p = uv * float(kWeatherMapSize) - 0.5f;
  const vec2 pFloor = floor(p);
  const vec2 f = p - pFloor;
  const ivec2 i0 = ivec2(pFloor) & mask;
  const ivec2 i1 = (i0 + 1) & mask;
  return mix(mix(fetchWeather(ivec2(i0.x, i0.y)), fetchWeather(ivec2(i1.x, i0.y)), f.x),
             mix(fetchWeather(ivec2(i0.x, i1.y)), fetchWeather(ivec2(i1.x, i1.y)), f.x), f.y);
}

VKFX_INLINE vec2 sampleCurl(vec2 uv) {
  const int mask = kCurlNoiseSize - 1;
  const vec2 p = uv * float(kCurlNoiseSize) - 0.5f;
  const vec2 pFloor = floor(p);
  const vec2 f = p - pFloor;
  const ivec2 i0 = ivec2(pFloor) & mask;
  const ivec2 i1 = (i0 + 1) & mask;
  const vec4 c = mix(mix(fetchCurl(ivec2(i0.x, i0.y)), fetchCurl(ivec2(i1.x, i0.y)), f.x),
                     mix(fetchCurl(ivec2(i0.x, i1.y)), fetchCurl(ivec2(i1.x, i1.y)), f.x), f.y);
  return vec2(c.x, c.y) * 2.0f - 1.0f;
}

VKFX_SHADER_END

#endif
