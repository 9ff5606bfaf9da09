// The terrain's surface per fragment, shared by its fragment shader and the C++ tests: a normal
// finer than the mesh (two octaves of value noise, 60 m and 11 m, bent into the interpolated
// normal), and materials by slope and altitude over the mesh's own colour: rock where the
// detailed surface is steep, snow where it is high and not too steep. The mesh's vertices are
// 150 m apart, so without these the light, the shadows and the haze fall on a surface smooth at
// that scale and in one colour per triangle. Closer, colour varied by material at the scales a
// pixel resolves, and an octave more (3 m) of relief, faded out with the pixel's footprint.
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

// The detail of the ground at world (x, z) in metres: its height's gradient (m per m) in xy, the
// two octaves' values in [0, 1) in z (60 m) and w (11 m), which break up the materials' edges
// and vary their colour (terrainDetailTint).
SHADER_INLINE vec4 terrainDetail(vec2 xz) {
  const float kLargeMetres = 60.0f;  // lattice spacing of each octave
  const float kSmallMetres = 11.0f;
  const float kLargeRelief = 9.0f;  // peak-to-peak height of each octave (m)
  const float kSmallRelief = 1.6f;
  const vec3 large = terrainNoise(xz / kLargeMetres);
  const vec3 small = terrainNoise(xz / kSmallMetres);
  const vec2 gradient = vec2(large.x, large.y) * (kLargeRelief / kLargeMetres) +
                        vec2(small.x, small.y) * (kSmallRelief / kSmallMetres);
  return vec4(gradient.x, gradient.y, large.z, small.z);
}

// The mesh's normal bent by the detail's height gradient (a heightfield's normal is
// (-dh/dx, 1, -dh/dz) before normalising; the mesh's own slope stays in it).
SHADER_INLINE vec3 terrainDetailNormal(vec3 meshNormal, vec4 detail) {
  const vec3 n = normalize(meshNormal);
  return normalize(n + vec3(-detail.x, 0.0f, -detail.y) * max(n.y, 0.0f));
}

// The materials' shares of the ground: x rock where the detailed surface is steep, y snow above
// the snow line where it is not too steep (the detail's value noise wavers both edges); the
// mesh's own colour (grass, earth) has the rest.
SHADER_INLINE vec2 terrainMaterialWeights(vec3 normal, float altitudeMetres, vec4 detail,
                                          TerrainMaterials m) {
  const float steepness = 1.0f - normal.y;
  const float waver = 0.7f * detail.z + 0.3f * detail.w - 0.5f;
  const float rock = smoothstep(m.rock.w - 0.04f, m.rock.w + 0.06f, steepness + 0.05f * waver);
  const float snowLine = m.snow.w + 250.0f * waver;
  const float snow = smoothstep(snowLine - 60.0f, snowLine + 60.0f, altitudeMetres) *
                     (1.0f - smoothstep(0.3f, 0.45f, steepness));
  return vec2(rock, snow);
}

// The albedo of the ground: the mesh's colour, rock and snow by their `weights`.
SHADER_INLINE vec3 terrainPaint(vec3 meshColour, vec2 weights, TerrainMaterials m) {
  return mix(mix(meshColour, vec3(m.rock), weights.x), vec3(m.snow), weights.y);
}

// The same from the surface: rock where it is steep, snow high up unless it is steep.
SHADER_INLINE vec3 terrainAlbedo(vec3 meshColour, vec3 normal, float altitudeMetres, vec4 detail,
                                 TerrainMaterials m) {
  return terrainPaint(meshColour, terrainMaterialWeights(normal, altitudeMetres, detail, m), m);
}

// --- Close up ---------------------------------------------------------------------------------
// What a low-flying pilot sees: colour varied by material at every scale a pixel resolves (the
// 60 m and 11 m octaves' values, and a close-up octave of 3 m), and below 0.75 m a pixel the
// close-up octave's relief too (rock rougher and more mottled than grass, snow smooth and even).
// Each octave fades out where a pixel covers more than a quarter of its wavelength: nothing
// shimmers, and where a pixel covers 15 m of ground or more it is what it was to the bit. Rock's
// close-up octave is projected three ways (triplanar): on a cliff a plan-view projection would
// smear it down the face. One close-up octave, not two: a second (0.8 m) cost about 1 ms more of
// the scene pass at 640x360 on lavapipe (docs/measurements.md).

const float kTerrainCloseMetres = 3.0f;  // the close-up octave's lattice spacing

// How much of an octave of `wavelengthMetres` a pixel covering `footprintMetres` of ground
// keeps: all of it up to an eighth of the wavelength, none from a quarter (four pixels a
// wavelength).
SHADER_INLINE float terrainOctaveKept(float wavelengthMetres, float footprintMetres) {
  return 1.0f - smoothstep(0.125f * wavelengthMetres, 0.25f * wavelengthMetres, footprintMetres);
}

// The close-up octave in one plane, at `p` (m) projected on it: xy the height's gradient in the
// plane (m per m of a relief of 1 m), z its value in [-0.5, 0.5).
SHADER_INLINE vec3 terrainCloseOctave(vec2 p) {
  const vec3 noise = terrainNoise(p / kTerrainCloseMetres);
  return vec3(vec2(noise.x, noise.y) / kTerrainCloseMetres, noise.z - 0.5f);
}

// The close-up detail of the ground at world `p` (m) whose (detail) normal is `normal`, with the
// materials' `weights` (terrainMaterialWeights) and a pixel covering `footprintMetres`: xyz what
// to add to the normal, w its value for the colour (terrainDetailTint). Exactly zero from a
// footprint of a quarter of the octave.
SHADER_INLINE vec4 terrainCloseDetail(vec3 p, vec3 normal, vec2 weights, float footprintMetres) {
  const float kept = terrainOctaveKept(kTerrainCloseMetres, footprintMetres);
  if (kept <= 0.0f) return vec4(0.0f);
  // Relief (m, peak to peak): grass and earth 0.6 (tussocks), rock 1, snow 0.15.
  const float relief = mix(mix(0.6f, 1.0f, weights.x), 0.15f, weights.y);
  // Plan view: heights over the ground.
  const vec3 top = terrainCloseOctave(vec2(p.x, p.z));
  vec3 bump = vec3(-top.x, 0.0f, -top.y);
  float value = top.z;
  if (weights.x > 0.0f) {
    // Rock: the plan view blended with the two side views by how the surface faces them.
    vec3 facing = abs(normal);
    facing *= facing;
    facing *= facing;
    facing /= facing.x + facing.y + facing.z;
    const vec3 side = terrainCloseOctave(vec2(p.z, p.y));   // faces +-x
    const vec3 front = terrainCloseOctave(vec2(p.x, p.y));  // faces +-z
    const vec3 rockBump = facing.y * bump + facing.x * vec3(0.0f, -side.y, -side.x) +
                          facing.z * vec3(-front.x, -front.y, 0.0f);
    const float rockValue = facing.y * value + facing.x * side.z + facing.z * front.z;
    bump = mix(bump, rockBump, weights.x);
    value = mix(value, rockValue, weights.x);
  }
  return vec4(bump * (relief * kept), value * kept);
}

// The colour of the ground's detail as a factor of the materials' albedo (1 on average), from
// the octaves a pixel covering `footprintMetres` resolves: the `detail` (terrainDetail) octaves'
// values and the close-up one's (`closeValue`, terrainCloseDetail's w, faded already). Grass
// drier and brighter or lusher and darker, rock mottled, snow nearly even. Exactly 1 where a
// pixel covers 15 m or more.
SHADER_INLINE vec3 terrainDetailTint(vec4 detail, float closeValue, vec2 weights,
                                     float footprintMetres) {
  const float value = 0.6f * terrainOctaveKept(60.0f, footprintMetres) * (detail.z - 0.5f) +
                      0.6f * terrainOctaveKept(11.0f, footprintMetres) * (detail.w - 0.5f) +
                      closeValue;
  const vec3 grass = vec3(1.0f) + value * vec3(0.7f, 0.5f, -0.15f);
  const vec3 rock = vec3(1.0f + 0.9f * value);
  const vec3 snow = vec3(1.0f + 0.1f * value);
  return mix(mix(grass, rock, weights.x), snow, weights.y);
}

SHADER_NAMESPACE_END

#endif
