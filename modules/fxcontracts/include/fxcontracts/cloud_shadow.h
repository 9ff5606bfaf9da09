// The cloud shadow map, the contract between the module that makes it (the clouds) and every
// pass that is shadowed by it (a host's terrain, the atmosphere's haze, a host's objects): one
// definition of its layout and of how it is read, compiled as GLSL and as C++.
//
// The map is a Beer shadow map (after Frostbite's "Beer shadow maps", Hillaire 2016): per texel
// the sun ray through it stores the clouds' whole optical depth and the altitudes of its first
// and last cloud, so a receiver at any altitude gets the optical depth of the cloud between
// it and the sun (all of it below the clouds, none above them, a linear ramp in between).
//
// Layout: one RGBA16F 2D image holding `cascades` square cascades side by side (cascade c is
// the texels [c N, (c + 1) N) x [0, N) for N texels per side). Texel: r the optical depth of
// the whole sun ray through the cloud layer (dimensionless, capped at kCloudShadowMaxDepth),
// g the altitude (m) of the ray's highest cloud, b the altitude of its lowest, a the terrain's
// shadow on the ray (below). A ray with no cloud stores 0 and the altitudes of the layer's top
// and bottom (so that filtering it with a cloudy neighbour fades the depth and keeps the
// neighbour's cloud where it is). Filter it linearly, clamped.
//
// The terrain's shadow (when the map was made with the host's terrain heightfield): the sun ray
// only climbs, so the points of a ray that the terrain hides from the sun are those below the
// altitude where it last leaves the ground on its way to the sun. `a` stores that altitude
// lowered by one texel's size (the rays of a texel's footprint differ by that much, and a
// receiver on a sunlit slope lies exactly at its own ray's last exit) and by the ramp below;
// a ray the terrain never hides stores an altitude below every receiver. Receivers at or above
// `a` + kCloudShadowTerrainRampMetres see the sun past the terrain, those at or below `a` do
// not. Without terrain every ray stores kCloudShadowNoTerrain. Unlike the clouds' channels this
// one is compared before it is filtered (percentage-closer filtering over the 2 x 2 texels a
// linear filter would blend): at a low sun neighbouring rays pass hundreds of metres apart in
// altitude, and the edge of a shadow is where one is hidden and the next is not, which
// blending the altitudes first would smear into a wrong altitude.
//
// Each cascade is an orthographic view along the sun: texel (i, j) of cascade c is the sun ray
// through the camera-relative point (u0 + (i + 0.5) s) U + (v0 + (j + 0.5) s) V, with U, V two
// unit vectors perpendicular to the cascade's light direction L and s its texel size. Cascades
// are centred near the camera, each larger than the one before, and snapped to whole texels in
// the world so that they do not swim when the camera moves. They are refreshed in turn, so each
// has its own U, V, L and origin: the parameters below, relative to this frame's camera, with
// the wind's drift since the cascade was made already folded into the origin.
#ifndef FX_CLOUD_SHADOW_H
#define FX_CLOUD_SHADOW_H

#include "fxcontracts/shader_interop.h"

FX_SHADER_BEGIN(fxcontracts::shader)

const int kCloudShadowMaxCascades = 4;
// Optical depth is stored up to this (exp(-64) is 1.6e-28: nothing passes).
const float kCloudShadowMaxDepth = 64.0f;
// Which channels a lookup reads (cloudShadowAt's `channels`, a constant at every call so the
// compiler drops the other read): the clouds' optical depth, the terrain's shadow, or both.
const uint kCloudShadowClouds = 1u;
const uint kCloudShadowTerrain = 2u;
const uint kCloudShadowBoth = 3u;
// The terrain's shadow fades over this many metres of altitude below its edge.
const float kCloudShadowTerrainRampMetres = 30.0f;
// The terrain channel of a map made without terrain: below every receiver.
const float kCloudShadowNoTerrain = -30000.0f;

// std140: 12 + 1 vec4s. Cascade c is cascade[3 c + 0..2]:
//   [3 c + 0] xyz U (unit, world), w u0: the cascade's lower edge along U (m, camera-relative)
//   [3 c + 1] xyz V (unit, world), w v0: its lower edge along V
//   [3 c + 2] xyz L (unit, towards the sun), w 1 / side (1/m), side = N x texel size
struct CloudShadowParameters {
  vec4 cascade[12];
  // x the number of cascades (0: no map, everything is lit), y texels per cascade side,
  // z the camera's altitude (m), w the fraction of a cascade's side over which it blends into
  // the next (and the last one into no shadow).
  vec4 info;
};
FX_STATIC_ASSERT(sizeof(CloudShadowParameters) == 13 * 16);

// Prototypes: the includer implements the filtered read of the map at `uv` (whole image, [0, 1]
// per axis; GLSL: textureLod on a linear, clamped sampler) and the gather of the terrain
// channel of the 2 x 2 texels that read blends, in textureGather's order (i, j + 1),
// (i + 1, j + 1), (i + 1, j), (i, j) (GLSL: textureGather(map, uv, 3)). C++: its own.
vec4 fetchCloudShadow(vec2 uv);
vec4 gatherCloudShadowTerrain(vec2 uv);

// Optical depth between the sun and a receiver at `altitudeMetres` from a (filtered) texel.
FX_INLINE float cloudShadowOpticalDepth(vec4 texel, float altitudeMetres) {
  const float front = texel.y;
  const float back = texel.z;
  const float inside = clamp((front - altitudeMetres) / max(front - back, 1.0f), 0.0f, 1.0f);
  return texel.x * inside;
}

// A cascade's [0, 1] coordinates of a camera-relative position.
FX_INLINE vec2 cloudShadowCascadeUv(vec4 u, vec4 v, vec4 light, vec3 relative) {
  return vec2(dot(vec3(u), relative) - u.w, dot(vec3(v), relative) - v.w) * light.w;
}

// How far inside its cascade a point at `uv` is: 1 in the middle, 0 at and beyond the edge
// band (a fraction `band` of the side).
FX_INLINE float cloudShadowCascadeWeight(vec2 uv, float band) {
  const vec2 edge = min(uv, vec2(1.0f) - uv);
  return clamp(min(edge.x, edge.y) / max(band, 1e-6f), 0.0f, 1.0f);
}

// The sun light a receiver at `altitudeMetres` gets past the terrain, 0 in the terrain's shadow
// and 1 out of it: compared with each of the 2 x 2 texels around the atlas coordinates `atlas`,
// then blended as a linear filter would (percentage-closer filtering). `info` is
// CloudShadowParameters::info.
FX_INLINE float cloudShadowTerrainLight(vec4 info, vec2 atlas, float altitudeMetres) {
  const vec2 size = vec2(info.x * info.y, info.y);
  const vec2 f = fract(atlas * size - 0.5f);
  const vec4 light = clamp(
      (vec4(altitudeMetres) - gatherCloudShadowTerrain(atlas)) / kCloudShadowTerrainRampMetres,
      vec4(0.0f), vec4(1.0f));
  return mix(mix(light.w, light.z, f.x), mix(light.x, light.y, f.x), f.y);
}

// The optical depth of the clouds (x) and the terrain's light (y) from cascade `c` at cascade
// coordinates `uv` for a receiver at an altitude, reading the `channels` asked for (the others
// are 0 and 1); `info` is CloudShadowParameters::info.
FX_INLINE vec2 cloudShadowCascadeSample(vec4 info, float c, vec2 uv, float altitudeMetres,
                                        uint channels) {
  const float n = info.y;
  // Clamp half a texel inside the cascade: linear filtering must not read its neighbour.
  const vec2 inside = clamp(uv, vec2(0.5f / n), vec2(1.0f - 0.5f / n));
  const vec2 atlas = vec2((c + inside.x) / max(info.x, 1.0f), inside.y);
  const float depth = (channels & kCloudShadowClouds) != 0u
                          ? cloudShadowOpticalDepth(fetchCloudShadow(atlas), altitudeMetres)
                          : 0.0f;
  const float terrain = (channels & kCloudShadowTerrain) != 0u
                            ? cloudShadowTerrainLight(info, atlas, altitudeMetres)
                            : 1.0f;
  return vec2(depth, terrain);
}

// Every cascade's coordinates of a camera-relative position: cascades 0 and 1 in `uv01`
// (xy, zw), 2 and 3 in `uv23`. They are affine in the position, so a rasteriser may compute
// them per vertex and interpolate them exactly. The arguments are the parameter block's fields
// one by one (CLOUD_SHADOW_COORDINATES below unpacks a block): a CPU Vulkan device copies a
// block passed whole into every invocation's memory.
FX_INLINE void cloudShadowCoordinatesOf(vec4 u0, vec4 v0, vec4 l0, vec4 u1, vec4 v1, vec4 l1,
                                        vec4 u2, vec4 v2, vec4 l2, vec4 u3, vec4 v3, vec4 l3,
                                        vec3 relative, OUT(vec4) uv01, OUT(vec4) uv23) {
  const vec2 c0 = cloudShadowCascadeUv(u0, v0, l0, relative);
  const vec2 c1 = cloudShadowCascadeUv(u1, v1, l1, relative);
  const vec2 c2 = cloudShadowCascadeUv(u2, v2, l2, relative);
  const vec2 c3 = cloudShadowCascadeUv(u3, v3, l3, relative);
  uv01 = vec4(c0.x, c0.y, c1.x, c1.y);
  uv23 = vec4(c2.x, c2.y, c3.x, c3.y);
}

// The sun a receiver at `altitudeMetres` gets, whose cascade coordinates are `uv01`, `uv23`
// (cloudShadowCoordinatesOf()): x the clouds' transmittance, y the terrain's light (0 in its
// shadow), of the `channels` read (kCloudShadowClouds, ...Terrain or ...Both; the other is 1).
// From the finest cascade that holds the receiver, blended into the next near its edge, and
// fading to no shadow at the edge of the last one. One read, two in a blend band.
FX_INLINE vec2 cloudShadowAt(vec4 info, vec4 uv01, vec4 uv23, float altitudeMetres, uint channels) {
  const float count = info.x;
  const float band = info.w;
  const vec2 c0 = vec2(uv01.x, uv01.y);
  const vec2 c1 = vec2(uv01.z, uv01.w);
  const vec2 c2 = vec2(uv23.x, uv23.y);
  const vec2 c3 = vec2(uv23.z, uv23.w);
  // Cascades the map does not have hold nothing.
  const float w0 = count > 0.5f ? cloudShadowCascadeWeight(c0, band) : 0.0f;
  const float w1 = count > 1.5f ? cloudShadowCascadeWeight(c1, band) : 0.0f;
  const float w2 = count > 2.5f ? cloudShadowCascadeWeight(c2, band) : 0.0f;
  const float w3 = count > 3.5f ? cloudShadowCascadeWeight(c3, band) : 0.0f;
  // The finest cascade that holds the position (a), and the next one (b).
  const float first = w0 > 0.0f ? 0.0f : w1 > 0.0f ? 1.0f : w2 > 0.0f ? 2.0f : 3.0f;
  const float weight = w0 > 0.0f ? w0 : w1 > 0.0f ? w1 : w2 > 0.0f ? w2 : w3;
  const vec2 a = first < 0.5f ? c0 : first < 1.5f ? c1 : first < 2.5f ? c2 : c3;
  const vec2 b = first < 0.5f ? c1 : first < 1.5f ? c2 : c3;
  // Loops of 0 or 1 trips: a CPU device skips them when no lane of a group needs them, where
  // it would run an if's body regardless. Past the last cascade the blend goes to no shadow
  // (no optical depth, full light).
  vec2 sampleA = vec2(0.0f, 1.0f);
  vec2 sampleB = vec2(0.0f, 1.0f);
  for (int i = 0; i < (weight > 0.0f ? 1 : 0); ++i) {
    sampleA = cloudShadowCascadeSample(info, first, a, altitudeMetres, channels);
  }
  for (int i = 0; i < (weight < 1.0f && first + 1.0f < count ? 1 : 0); ++i) {
    sampleB = cloudShadowCascadeSample(info, first + 1.0f, b, altitudeMetres, channels);
  }
  const vec2 blended = sampleA * weight + sampleB * (1.0f - weight);
  return vec2(exp(-blended.x), blended.y);
}

// cloudShadowAt() at a camera-relative position (metres; y up).
FX_INLINE vec2 cloudShadowAtPosition(IN(CloudShadowParameters) p, vec3 relative) {
  if (p.info.x < 0.5f) return vec2(1.0f);  // no map
  vec4 uv01;
  vec4 uv23;
  cloudShadowCoordinatesOf(p.cascade[0], p.cascade[1], p.cascade[2], p.cascade[3], p.cascade[4],
                           p.cascade[5], p.cascade[6], p.cascade[7], p.cascade[8], p.cascade[9],
                           p.cascade[10], p.cascade[11], relative, uv01, uv23);
  return cloudShadowAt(p.info, uv01, uv23, p.info.z + relative.y, kCloudShadowBoth);
}

// For shaders: cloudShadowCoordinatesOf() with the fields of a parameter block in a uniform
// block, read in place.
#define CLOUD_SHADOW_COORDINATES(block, relative, uv01, uv23)                                      \
  cloudShadowCoordinatesOf(block.cascade[0], block.cascade[1], block.cascade[2], block.cascade[3], \
                           block.cascade[4], block.cascade[5], block.cascade[6], block.cascade[7], \
                           block.cascade[8], block.cascade[9], block.cascade[10],                  \
                           block.cascade[11], relative, uv01, uv23)

FX_SHADER_END

#endif
