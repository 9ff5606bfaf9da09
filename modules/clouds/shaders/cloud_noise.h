// Tileable procedural noise for the cloud textures, deterministic from a seed: integer hashing,
// periodic gradient (Perlin) noise, periodic cellular (Worley) noise on a stratified grid, and
// their fractal sums. "Periodic" means the noise repeats every `period` lattice cells, so the
// textures tile. References: Perlin 2002 (improved noise fade); Worley 1996; Schneider 2015/2017
// (Perlin-Worley); Jarzynski & Olano 2020 (pcg3d hash).
#ifndef CLOUDS_CLOUD_NOISE_H
#define CLOUDS_CLOUD_NOISE_H

#include "cloud_math.h"

FX_SHADER_BEGIN(clouds::shader)

FX_INLINE uvec3 pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

// Three uniform values in [0, 1) for an integer lattice cell and a seed.
FX_INLINE vec3 hashCell(ivec3 cell, uint seed) {
  const uvec3 h = pcg3d(uvec3(cell) + uvec3(seed, seed * 7919u, seed * 104729u));
  return vec3(h >> 8u) * (1.0f / 16777216.0f);
}

// Wraps a lattice coordinate into [0, period); valid for coordinates >= -period.
FX_INLINE ivec3 wrapCell(ivec3 cell, int period) {
  return (cell + ivec3(period)) % period;
}

FX_INLINE float fade(float t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

FX_INLINE float gradientDot(ivec3 cell, vec3 offset, int period, uint seed) {
  const vec3 g = hashCell(wrapCell(cell, period), seed) * 2.0f - 1.0f;
  return dot(g, offset);
}

// Periodic gradient noise, period `period` cells, p in cell units (>= 0). Output about [-1, 1].
FX_INLINE float perlinNoise(vec3 p, int period, uint seed) {
  const vec3 cellFloor = floor(p);
  const ivec3 i = ivec3(cellFloor);
  const vec3 f = p - cellFloor;
  const float n000 = gradientDot(i + ivec3(0, 0, 0), f - vec3(0.0f, 0.0f, 0.0f), period, seed);
  const float n100 = gradientDot(i + ivec3(1, 0, 0), f - vec3(1.0f, 0.0f, 0.0f), period, seed);
  const float n010 = gradientDot(i + ivec3(0, 1, 0), f - vec3(0.0f, 1.0f, 0.0f), period, seed);
  const float n110 = gradientDot(i + ivec3(1, 1, 0), f - vec3(1.0f, 1.0f, 0.0f), period, seed);
  const float n001 = gradientDot(i + ivec3(0, 0, 1), f - vec3(0.0f, 0.0f, 1.0f), period, seed);
  const float n101 = gradientDot(i + ivec3(1, 0, 1), f - vec3(1.0f, 0.0f, 1.0f), period, seed);
  const float n011 = gradientDot(i + ivec3(0, 1, 1), f - vec3(0.0f, 1.0f, 1.0f), period, seed);
  const float n111 = gradientDot(i + ivec3(1, 1, 1), f - vec3(1.0f, 1.0f, 1.0f), period, seed);
  const vec3 u = vec3(fade(f.x), fade(f.y), fade(f.z));
  const float x00 = mix(n000, n100, u.x);
  const float x10 = mix(n010, n110, u.x);
  const float x01 = mix(n001, n101, u.x);
  const float x11 = mix(n011, n111, u.x);
  return mix(mix(x00, x10, u.y), mix(x01, x11, u.y), u.z) * 1.5f;
}

// Fractal sum of `octaves` periodic Perlin octaves starting at `period` cells over the tile;
// `uvw` in [0, 1) tile units. Output in [0, 1].
FX_INLINE float perlinFbm(vec3 uvw, int period, int octaves, uint seed) {
  float sum = 0.0f;
  float amplitude = 1.0f;
  float total = 0.0f;
  int p = period;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * perlinNoise(uvw * float(p), p, seed + uint(o) * 31u);
    total += amplitude;
    amplitude *= 0.5f;
    p *= 2;
  }
  return saturate(sum / total * 0.5f + 0.5f);
}

// Periodic cellular noise with one feature point per cell (stratified, so only the 27
// neighbouring cells can hold the nearest point). Returns 1 - F1 in [0, 1] (inverted: cloud
// "puffs" are bright), with F1 in cell units.
FX_INLINE float worleyNoise(vec3 uvw, int cells, uint seed) {
  const vec3 p = uvw * float(cells);
  const vec3 cellFloor = floor(p);
  const ivec3 base = ivec3(cellFloor);
  const vec3 f = p - cellFloor;
  float nearest = 1e9f;
  for (int z = -1; z <= 1; ++z) {
    for (int y = -1; y <= 1; ++y) {
      for (int x = -1; x <= 1; ++x) {
        const ivec3 offset = ivec3(x, y, z);
        const vec3 feature = vec3(offset) + hashCell(wrapCell(base + offset, cells), seed);
        const vec3 d = feature - f;
        nearest = min(nearest, dot(d, d));
      }
    }
  }
  return saturate(1.0f - sqrt(nearest));
}

// Worley fBm over three octaves (cells, 2 cells, 4 cells) with Nubis' 0.625 / 0.25 / 0.125.
FX_INLINE float worleyFbm(vec3 uvw, int cells, uint seed) {
  return worleyNoise(uvw, cells, seed) * 0.625f + worleyNoise(uvw, cells * 2, seed + 1u) * 0.25f +
         worleyNoise(uvw, cells * 4, seed + 2u) * 0.125f;
}

// Low-frequency shape texel (128^3 texture): R Perlin-Worley, G/B/A Worley fBm at increasing
// frequency. Perlin-Worley as in Schneider 2017, remap(perlin, 1 - worley, 1, 0, 1): the web
// of Worley cells is subtracted from the low regions of connected Perlin noise, leaving round
// shapes. (The dilating form of Hillaire's generator, remap(perlin, 0, 1, worley, 1), leaves
// so little empty space that coverage 0.5 is already overcast.)
FX_INLINE vec4 lowFrequencyNoiseTexel(vec3 uvw, uint seed) {
  const float perlin = perlinFbm(uvw, 4, 3, seed);
  const float worley4 = worleyNoise(uvw, 4, seed + 10u);
  const float worley8 = worleyNoise(uvw, 8, seed + 11u);
  const float worley16 = worleyNoise(uvw, 16, seed + 12u);
  const float worley32 = worleyNoise(uvw, 32, seed + 13u);
  const float worley64 = worleyNoise(uvw, 64, seed + 14u);
  const float fbm4 = worley4 * 0.625f + worley8 * 0.25f + worley16 * 0.125f;
  const float fbm8 = worley8 * 0.625f + worley16 * 0.25f + worley32 * 0.125f;
  const float fbm16 = worley16 * 0.625f + worley32 * 0.25f + worley64 * 0.125f;
  const float perlinWorley = saturate(remap(perlin, 1.0f - fbm4, 1.0f, 0.0f, 1.0f));
  return vec4(perlinWorley, fbm4, fbm8, fbm16);
}

// High-frequency detail texel (32^3 texture): Worley fBm at three frequencies; A unused (1).
FX_INLINE vec4 highFrequencyNoiseTexel(vec3 uvw, uint seed) {
  return vec4(worleyFbm(uvw, 2, seed + 20u), worleyFbm(uvw, 4, seed + 23u),
              worleyFbm(uvw, 8, seed + 26u), 1.0f);
}

// What the shape noise texture holds: the base shape of the clouds, in [0, 1], the Perlin-Worley
// noise remapped by the low-frequency Worley fBm of the other channels (Schneider 2015). Made
// once per texel when the texture is made, so a sample reads one value, not four channels.
FX_INLINE float shapeNoiseValue(vec4 channels) {
  const float lowFrequencyFbm =
      dot(vec3(channels.y, channels.z, channels.w), vec3(0.625f, 0.25f, 0.125f));
  return saturate(remap(channels.x, lowFrequencyFbm - 1.0f, 1.0f, 0.0f, 1.0f));
}

// What the detail noise texture holds: the Worley fBm of its three frequencies, in [0, 1].
FX_INLINE float detailNoiseValue(vec4 channels) {
  return dot(vec3(channels.x, channels.y, channels.z), vec3(0.625f, 0.25f, 0.125f));
}

// Periodic alligator noise (the cellular noise of SideFX's HDK example, Nubis³'s billows): each
// cell holds one feature point and a random weight; a point takes smoothstep(1 - d) x weight of
// every feature within one cell of it and returns the largest take minus the second largest.
// So cell interiors swell into round lobes and the lobes' shared borders crack to 0: Worley's
// puffs with creases between them. p in cell units (>= 0), period `period` cells; in [0, 1].
FX_INLINE float alligatorNoise(vec3 p, int period, uint seed) {
  const vec3 cellFloor = floor(p);
  const ivec3 base = ivec3(cellFloor);
  const vec3 f = p - cellFloor;
  float largest = 0.0f;
  float second = 0.0f;
  for (int z = -1; z <= 1; ++z) {
    for (int y = -1; y <= 1; ++y) {
      for (int x = -1; x <= 1; ++x) {
        const ivec3 offset = ivec3(x, y, z);
        const ivec3 cell = wrapCell(base + offset, period);
        const vec3 feature = vec3(offset) + hashCell(cell, seed);
        const float d = length(feature - f);
        const float take = smoothstep(0.0f, 1.0f, 1.0f - d) * hashCell(cell, seed + 1u).x;
        second = max(second, min(largest, take));
        largest = max(largest, take);
      }
    }
  }
  return largest - second;
}

// Fractal sum of `octaves` alligator octaves from `period` cells over the tile, each twice the
// frequency and half the amplitude of the one before; `uvw` in tile units. In [0, 1].
FX_INLINE float alligatorFbm(vec3 uvw, int period, int octaves, uint seed) {
  float sum = 0.0f;
  float amplitude = 1.0f;
  float total = 0.0f;
  int p = period;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * alligatorNoise(uvw * float(p), p, seed + uint(o) * 37u);
    total += amplitude;
    amplitude *= 0.5f;
    p *= 2;
  }
  return sum / total;
}

// The curls of the curly alligator: a periodic displacement (tile units) of up to about
// `amplitude`, three independent gradient-noise fields of `period` cells. A displaced periodic
// noise is still periodic, so the texture keeps tiling.
FX_INLINE vec3 curlyDisplacement(vec3 uvw, int period, float amplitude, uint seed) {
  return vec3(perlinFbm(uvw, period, 2, seed), perlinFbm(uvw, period, 2, seed + 101u),
              perlinFbm(uvw, period, 2, seed + 211u)) *
             (2.0f * amplitude) -
         amplitude;
}

// A texel of the hero clouds' detail noise (Schneider 2023, Nubis³'s "voxel cloud noise", 128^3
// and four channels over kHeroNoiseTileMetres): R and G the curly alligator at a low and a high
// frequency (the wisps: alligator noise through curled space, stretched into layered strands),
// B and A the alligator at a low and a high frequency (the billows). cloud_hero.h's
// heroUprezzedDensity() blends them by the voxel's dimensional profile and detail type.
// Each channel is stretched by kAlligatorContrast: two octaves of alligator noise rarely reach
// past 0.6, and the erosion wants the whole range.
const float kAlligatorContrast = 1.6f;
FX_INLINE vec4 heroNoiseTexel(vec3 uvw, uint seed) {
  const vec3 curled = uvw + curlyDisplacement(uvw, 2, 0.12f, seed + 60u);
  const vec4 channels =
      vec4(alligatorFbm(curled, 2, 2, seed + 61u), alligatorFbm(curled, 8, 2, seed + 62u),
           alligatorFbm(uvw, 2, 2, seed + 63u), alligatorFbm(uvw, 8, 2, seed + 64u));
  return clamp(channels * kAlligatorContrast, vec4(0.0f), vec4(1.0f));
}

// Curl of a periodic 2D potential (Perlin fBm), by central differences; unit-range output
// encoded as 0.5 + 0.5 * curl in RG. Used to swirl the detail noise.
FX_INLINE vec2 curlNoiseTexel(vec2 uv, float texelSize, uint seed) {
  const float e = texelSize;
  const float n1 = perlinFbm(vec3(uv + vec2(0.0f, e), 0.0f), 4, 3, seed + 40u);
  const float n2 = perlinFbm(vec3(uv - vec2(0.0f, e), 0.0f), 4, 3, seed + 40u);
  const float n3 = perlinFbm(vec3(uv + vec2(e, 0.0f), 0.0f), 4, 3, seed + 40u);
  const float n4 = perlinFbm(vec3(uv - vec2(e, 0.0f), 0.0f), 4, 3, seed + 40u);
  // Normalise by a typical gradient magnitude so the field uses the 8-bit range.
  const vec2 curl = vec2(n1 - n2, n4 - n3) / (2.0f * e) * 0.05f;
  return clamp(curl, vec2(-1.0f), vec2(1.0f)) * 0.5f + 0.5f;
}

FX_SHADER_END

#endif
