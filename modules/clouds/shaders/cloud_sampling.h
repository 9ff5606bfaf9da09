// Texture sampling for the cloud model, shared by GPU and CPU. Shaders implement the fetch
// prototypes with imageLoad on RGBA8 textures; the CPU reference with array lookups of the
// same (read-back) texels. Filtering is done here, by hand: trilinear from fetches is about
// twice as fast as sampler filtering of 3D textures on lavapipe, and it makes GPU and CPU
// filter identically. Coordinates are in tile units and wrap (the textures tile).
#ifndef CLOUDS_CLOUD_SAMPLING_H
#define CLOUDS_CLOUD_SAMPLING_H

#include "cloud_types.h"

FX_SHADER_BEGIN(clouds::shader)

// Prototypes: texel coordinates are already wrapped into the texture (for the 3D noises, into
// one level of the mip chain their image holds).
vec4 fetchShapeNoise(ivec3 texel);
vec4 fetchDetailNoise(ivec3 texel);
vec4 fetchWeather(ivec2 texel);
vec4 fetchCurl(ivec2 texel);
vec4 fetchWeatherMaxFine(ivec2 texel);    // kWeatherMaxFineSize^2
vec4 fetchWeatherMaxCoarse(ivec2 texel);  // kWeatherMaxCoarseSize^2

// Where `level` of an n^3 noise's mip chain starts in its n x n x 3n/2 image. Level 0 fills the
// first n slices; level L >= 1 (n >> L texels a side) is the cube at x = n - 2 (n >> L) on the
// slices above (z = n), so the levels lie side by side along x: [0, n/2), [n/2, 3n/4), ...
FX_INLINE ivec3 noiseLevelOrigin(int level, int n) {
  return level > 0 ? ivec3(n - 2 * (n >> level), 0, n) : ivec3(0);
}

// The mip level at which one texel of a noise, `texelMetres` apart at level 0, is as wide as
// `footprintMetres`, what one pixel sees of the sample: log2 of their ratio, rounded down or up
// by `dither` in [0, 1) so that the frames a pixel averages blend the two levels around it (a
// blend within one sample would double its 8 fetches). 0 for footprints below one texel.
FX_INLINE int noiseLevel(float footprintMetres, float texelMetres, float dither, int levels) {
  const float lod = log2(max(footprintMetres, 1e-20f) / texelMetres);
  return clamp(int(floor(lod + dither)), 0, levels - 1);
}

// The 3D noises are packed for their filtering: level L's texel (x, y, z) holds in RGBA the
// level's values at (x, y, z), (x + 1, y, z), (x, y + 1, z) and (x + 1, y + 1, z) (wrapping
// round the level, which tiles), so that the 8 values a trilinear sample blends come in 2
// fetches, not 8 (noise_mip.comp packs them). On lavapipe an image fetch is a gather over the
// lanes, and the march fetches these noises at every sample.
struct TrilinearCell {
  ivec3 i0;  // the cell's lowest corner (address in the chain's image)
  int z1;    // the z of its upper layer
  vec3 f;    // the point's place in the cell
};

FX_INLINE TrilinearCell trilinearCell(vec3 uvw, int level, int n) {
  const int size = n >> level;
  const ivec3 origin = noiseLevelOrigin(level, n);
  const vec3 p = uvw * float(size) - 0.5f;
  const vec3 pFloor = floor(p);
  TrilinearCell c;
  c.f = p - pFloor;
  c.i0 = (ivec3(pFloor) & (size - 1)) + origin;
  c.z1 = ((int(pFloor.z) + 1) & (size - 1)) + origin.z;
  return c;
}

// The trilinear blend of a packed cell's two texels (its lower and upper layer), each read by
// `fetch` (a 3D fetch prototype above): one body for both noises, since GLSL cannot pass a
// function.
#define CLOUDS_PACKED_TRILINEAR(fetch, c) \
  mix(bilinearOfPacked(fetch(c.i0), c.f), \
      bilinearOfPacked(fetch(ivec3(c.i0.x, c.i0.y, c.z1)), c.f), c.f.z)

// The bilinear blend over x and y of a packed texel (see above) at the place `f` in its cell.
FX_INLINE float bilinearOfPacked(vec4 texel, vec3 f) {
  return mix(mix(texel.x, texel.y, f.x), mix(texel.z, texel.w, f.x), f.y);
}

// The shape noise's value (shapeNoiseValue()) at `uvw` (tiles) from `level` of its chain.
FX_INLINE float sampleShapeNoise(vec3 uvw, int level) {
  const TrilinearCell c = trilinearCell(uvw, level, kShapeNoiseSize);
  return CLOUDS_PACKED_TRILINEAR(fetchShapeNoise, c);
}

// The detail noise's value (detailNoiseValue()) at `uvw` (tiles) from `level` of its chain.
FX_INLINE float sampleDetailNoise(vec3 uvw, int level) {
  const TrilinearCell c = trilinearCell(uvw, level, kDetailNoiseSize);
  return CLOUDS_PACKED_TRILINEAR(fetchDetailNoise, c);
}

FX_INLINE vec4 sampleWeather(vec2 uv) {
  const int mask = kWeatherMapSize - 1;
  const vec2 p = uv * float(kWeatherMapSize) - 0.5f;
  const vec2 pFloor = floor(p);
  const vec2 f = p - pFloor;
  const ivec2 i0 = ivec2(pFloor) & mask;
  const ivec2 i1 = (i0 + 1) & mask;
  return mix(mix(fetchWeather(ivec2(i0.x, i0.y)), fetchWeather(ivec2(i1.x, i0.y)), f.x),
             mix(fetchWeather(ivec2(i0.x, i1.y)), fetchWeather(ivec2(i1.x, i1.y)), f.x), f.y);
}

FX_INLINE vec2 sampleCurl(vec2 uv) {
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

FX_SHADER_END

#endif
