// The terrain's shadow on one sun ray of the cloud shadow map (its alpha channel,
// fxcontracts/cloud_shadow.h), shared by terrain_shadow_map.comp and the CPU reference: the ray is
// walked over the host's heightfield from where it is at the terrain's lowest altitude to where
// it clears the highest, and the altitude where it last leaves the ground is the top of the
// shadow (everything on the ray below it is hidden from the sun; the ray only climbs).
//
// The includer implements the heightfield's filtered read, `fetchTerrainHeight(uv)` (altitude in
// metres at [0, 1]^2 heightfield coordinates, u along world x and v along world z).
#ifndef CLOUDS_TERRAIN_SHADOW_MARCH_H
#define CLOUDS_TERRAIN_SHADOW_MARCH_H

#include "cloud_types.h"
#include "fxcontracts/cloud_shadow.h"

FX_SHADER_BEGIN(clouds::shader)

float fetchTerrainHeight(vec2 uv);

// The interval of ray distances whose (x, z) lie inside the heightfield, intersected with
// [start, end]; empty (x > y) when the ray misses it.
FX_INLINE vec2 clipToHeightfield(vec2 origin, vec2 direction, float start, float end,
                                 IN(TerrainShadowConstants) t) {
  const vec2 size = vec2(1.0f) / t.heightInverseSize;
  const vec2 low = t.heightOriginMetres;
  const vec2 high = t.heightOriginMetres + size;
  vec2 range = vec2(start, end);
  for (int axis = 0; axis < 2; ++axis) {
    const float o = axis == 0 ? origin.x : origin.y;
    const float d = axis == 0 ? direction.x : direction.y;
    const float lo = axis == 0 ? low.x : low.y;
    const float hi = axis == 0 ? high.x : high.y;
    if (abs(d) < 1e-9f) {
      if (o < lo || o > hi) range = vec2(1.0f, 0.0f);
    } else {
      const float a = (lo - o) / d;
      const float b = (hi - o) / d;
      range = vec2(max(range.x, min(a, b)), min(range.y, max(a, b)));
    }
  }
  return range;
}

// Height of the terrain above the ray at distance `s` along it (negative: the ray is above).
FX_INLINE float terrainAboveRay(vec3 base, vec3 light, float baseAltitude, float s,
                                IN(TerrainShadowConstants) t) {
  const vec2 p = vec2(base.x + light.x * s, base.z + light.z * s);
  const vec2 uv = (p - t.heightOriginMetres) * t.heightInverseSize;
  return fetchTerrainHeight(uv) - (baseAltitude + light.y * s);
}

// The altitude (m) below which the sun ray through the camera-relative point `base` along
// `light` (unit, light.y > 0) is in the terrain's shadow, sampled at t.steps + 1 points; a ray
// the terrain never hides gets the terrain's lowest altitude. `cameraAltitude` in metres.
FX_INLINE float terrainShadowTop(vec3 base, vec3 light, float cameraAltitude,
                                 IN(TerrainShadowConstants) t) {
  const float baseAltitude = cameraAltitude + base.y;
  // The ray between the terrain's lowest and highest altitude, and over the heightfield.
  const vec2 range = clipToHeightfield(vec2(base.x, base.z), vec2(light.x, light.z),
                                       (t.minAltitudeMetres - baseAltitude) / light.y,
                                       (t.maxAltitudeMetres - baseAltitude) / light.y, t);
  float top = t.minAltitudeMetres;
  const int steps = int(max(t.steps, 1u));
  const float stepLength = max(range.y - range.x, 0.0f) / float(steps);
  // Loop of 0 or steps + 1 trips (no work for a ray that misses the heightfield).
  const int samples = range.y > range.x ? steps + 1 : 0;
  float previous = -1.0f;  // the terrain above the ray at the previous sample
  for (int i = 0; i < samples; ++i) {
    const float s = range.x + float(i) * stepLength;
    const float above = terrainAboveRay(base, light, baseAltitude, s, t);
    if (previous >= 0.0f && above < 0.0f) {
      // The ray left the ground between the two samples: where, linearly.
      const float exit = s - stepLength * (-above / (previous - above));
      top = baseAltitude + light.y * exit;
    }
    previous = above;
  }
  // Still in the ground at the heightfield's edge or its highest altitude: it leaves there.
  if (samples > 0 && previous >= 0.0f) top = baseAltitude + light.y * range.y;
  return top;
}

// The terrain channel of texel `texel` of the cascade in `t.cascade`: the ray through the
// texel's centre (as marchShadowTexel() places it), lowered as fxcontracts/cloud_shadow.h says.
FX_INLINE float terrainShadowTexel(IN(TerrainShadowConstants) t, uvec2 texel) {
  const ShadowMapConstants c = t.cascade;
  const float size = c.light.w;
  const vec3 base = vec3(c.axisU) * (c.axisU.w + float(texel.x) * size) +
                    vec3(c.axisV) * (c.axisV.w + float(texel.y) * size);
  return terrainShadowTop(base, vec3(c.light), t.cameraAltitudeMetres, t) - t.biasMetres;
}

FX_SHADER_END

#endif
