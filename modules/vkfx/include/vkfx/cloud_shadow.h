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
// g the altitude (m) of the ray's highest cloud, b the altitude of its lowest, a 1. A ray
// with no cloud stores 0 and the altitudes of the layer's bottom. Filter it linearly, clamped.
//
// Each cascade is an orthographic view along the sun: texel (i, j) of cascade c is the sun ray
// through the camera-relative point (u0 + (i + 0.5) s) U + (v0 + (j + 0.5) s) V, with U, V two
// unit vectors perpendicular to the cascade's light direction L and s its texel size. Cascades
// are centred near the camera, each larger than the one before, and snapped to whole texels in
// the world so that they do not swim when the camera moves. They are refreshed in turn, so each
// has its own U, V, L and origin: the parameters below, relative to this frame's camera, with
// the wind's drift since the cascade was made already folded into the origin.
#ifndef VKFX_CLOUD_SHADOW_H
#define VKFX_CLOUD_SHADOW_H

#include "vkfx/shader_interop.h"

VKFX_SHADER_BEGIN(vkfx::shader)

const int kCloudShadowMaxCascades = 4;
// Optical depth is stored up to this (exp(-64) is 1.6e-28: nothing passes).
const float kCloudShadowMaxDepth = 64.0f;

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
VKFX_STATIC_ASSERT(sizeof(CloudShadowParameters) == 13 * 16);

// Prototype: the includer implements the filtered read of the map at `uv` (whole image, [0, 1]
// per axis): GLSL with textureLod on a linear, clamped sampler; C++ with its own bilinear.
vec4 fetchCloudShadow(vec2 uv);

// Optical depth between the sun and a receiver at `altitudeMetres` from a (filtered) texel.
VKFX_INLINE float cloudShadowOpticalDepth(vec4 texel, float altitudeMetres) {
  const float front = texel.y;
  const float back = texel.z;
  const float inside = clamp((front - altitudeMetres) / max(front - back, 1.0f), 0.0f, 1.0f);
  return texel.x * inside;
}

// The cascade's [0, 1] coordinates of a camera-relative position.
VKFX_INLINE vec2 cloudShadowCascadeUv(IN(CloudShadowParameters) p, int c, vec3 relative) {
  const vec4 u = p.cascade[3 * c];
  const vec4 v = p.cascade[3 * c + 1];
  const float inverseSide = p.cascade[3 * c + 2].w;
  return vec2(dot(vec3(u), relative) - u.w, dot(vec3(v), relative) - v.w) * inverseSide;
}

// How far inside its cascade a point is: 1 in the middle, 0 at (and beyond) the edge band.
VKFX_INLINE float cloudShadowCascadeWeight(vec2 uv, float band) {
  const vec2 edge = min(uv, vec2(1.0f) - uv);
  return clamp(min(edge.x, edge.y) / max(band, 1e-6f), 0.0f, 1.0f);
}

// Optical depth from cascade `c` at a camera-relative position.
VKFX_INLINE float cloudShadowCascadeDepth(IN(CloudShadowParameters) p, int c, vec3 relative) {
  const float n = p.info.y;
  const float cascades = p.info.x;
  // Clamp half a texel inside the cascade: linear filtering must not read its neighbour.
  const vec2 uv =
      clamp(cloudShadowCascadeUv(p, c, relative), vec2(0.5f / n), vec2(1.0f - 0.5f / n));
  const vec2 atlas = vec2((float(c) + uv.x) / cascades, uv.y);
  return cloudShadowOpticalDepth(fetchCloudShadow(atlas), p.info.z + relative.y);
}

// The clouds' transmittance towards the sun at a camera-relative position (metres; y up):
// from the finest cascade that holds it, blended into the next one near its edge, and fading
// to 1 (no shadow) at the edge of the last one. Two reads at most.
VKFX_INLINE float cloudShadowTransmittance(IN(CloudShadowParameters) p, vec3 relative) {
  const int cascades = int(p.info.x);
  const float band = p.info.w;
  // The finest cascade whose inner part holds the point, and its weight.
  int first = cascades;
  float weight = 0.0f;
  for (int c = cascades - 1; c >= 0; --c) {
    const float w = cloudShadowCascadeWeight(cloudShadowCascadeUv(p, c, relative), band);
    if (w > 0.0f) {
      first = c;
      weight = w;
    }
  }
  if (first >= cascades) return 1.0f;
  const float depth = cloudShadowCascadeDepth(p, first, relative);
  float blended = depth * weight;
  if (weight < 1.0f) {
    const float next =
        first + 1 < cascades ? cloudShadowCascadeDepth(p, first + 1, relative) : 0.0f;
    blended += next * (1.0f - weight);
  }
  return exp(-blended);
}

VKFX_SHADER_END

#endif
