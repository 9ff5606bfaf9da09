// The terrain's surface per fragment, shared by its fragment shader and the C++ tests: a normal
// finer than the mesh (two octaves of value noise, 60 m and 11 m, bent into the interpolated
// normal), and materials by slope and altitude over the mesh's own colour: rock where the
// detailed surface is steep, snow where it is high and not too steep. The mesh's vertices are
// 150 m apart, so without these the light, the shadows and the haze fall on a surface smooth at
// that scale and in one colour per triangle.
#ifndef SAMPLE_SHADERS_TERRAIN_MATERIAL_H
#define SAMPLE_SHADERS_TERRAIN_MATERIAL_H

#include "interop.h"

SHADER_NAMESPACE_BEGIN

// The materials a scene's terrain is painted with (SceneFrame): rgb the albedo, w a threshold.
struct TerrainMaterials {
  vec4 rock;  // w: the slope (1 - normal.y) where rock starts to show
  vec4 snow;  // w: the altitude (m) where snow starts to lie
};

// A hash of an integer lattice point in [0, 1).
SHADER_INLINE float terrainHash(int x, int y) {
  uint h = uint(x) * 0x8da6b343u ^ uint(y) * 0xd8163841u;
  h ^= h >> 15u;
  h *= 0x2c1b3c6du;
  h ^= h >> 12u;
  h *= 0x297a2d39u;
  h ^= h >> 15u;
  return float(h >> 8u) * (1.0f / 16777216.0f);
}

// Value noise in [0, 1) at `p` (lattice units) and its gradient (xy: d/dx, d/dy; z: the value),
// with a smooth (C1) fade.
SHADER_INLINE vec3 terrainNoise(vec2 p) {
  const vec2 cell = floor(p);
  const vec2 f = p - cell;
  const vec2 fade = f * f * (3.0f - 2.0f * f);
  const vec2 slope = 6.0f * f * (1.0f - f);
  const int x = int(cell.x);
  const int y = int(cell.y);
  const float a = terrainHash(x, y);
  const float b = terrainHash(x + 1, y);
  const float c = terrainHash(x, y + 1);
  const float d = terrainHash(x + 1, y + 1);
  const float value = mix(mix(a, b, fade.x), mix(c, d, fade.x), fade.y);
  const float dx = slope.x * mix(b - a, d - c, fade.y);
  const float dy = slope.y * mix(c - a, d - b, fade.x);
  return vec3(dx, dy, value);
}

// The detail of the ground at world (x, z) in metres: its height's gradient (m per m) in xy, a
// value in [0, 1) in z (to break up the materials' edges).
SHADER_INLINE vec3 terrainDetail(vec2 xz) {
  const float kLargeMetres = 60.0f;  // lattice spacing of each octave
  const float kSmallMetres = 11.0f;
  const float kLargeRelief = 9.0f;  // peak-to-peak height of each octave (m)
  const float kSmallRelief = 1.6f;
  const vec3 large = terrainNoise(xz / kLargeMetres);
  const vec3 small = terrainNoise(xz / kSmallMetres);
  const vec2 gradient = vec2(large.x, large.y) * (kLargeRelief / kLargeMetres) +
                        vec2(small.x, small.y) * (kSmallRelief / kSmallMetres);
  return vec3(gradient.x, gradient.y, 0.7f * large.z + 0.3f * small.z);
}

// The mesh's normal bent by the detail's height gradient (a heightfield's normal is
// (-dh/dx, 1, -dh/dz) before normalising; the mesh's own slope stays in it).
SHADER_INLINE vec3 terrainDetailNormal(vec3 meshNormal, vec3 detail) {
  const vec3 n = normalize(meshNormal);
  return normalize(n + vec3(-detail.x, 0.0f, -detail.y) * max(n.y, 0.0f));
}

// The albedo of the ground: the mesh's colour, rock where the detailed surface is steep, snow
// above the snow line where it is not too steep (the detail's value noise wavers both edges).
SHADER_INLINE vec3 terrainAlbedo(vec3 meshColour, vec3 normal, float altitudeMetres, vec3 detail,
                                 TerrainMaterials m) {
  const float steepness = 1.0f - normal.y;
  const float waver = detail.z - 0.5f;
  const float rock = smoothstep(m.rock.w - 0.04f, m.rock.w + 0.06f, steepness + 0.05f * waver);
  const float snowLine = m.snow.w + 250.0f * waver;
  const float snow = smoothstep(snowLine - 60.0f, snowLine + 60.0f, altitudeMetres) *
                     (1.0f - smoothstep(0.3f, 0.45f, steepness));
  const vec3 ground = mix(meshColour, vec3(m.rock), rock);
  return mix(ground, vec3(m.snow), snow);
}

SHADER_NAMESPACE_END

#endif
