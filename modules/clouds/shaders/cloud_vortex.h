// The superstorm (Schneider 2022, "The Real-Time Volumetric Superstorms of Horizon Forbidden
// West"; seed 001's M.D.R. vortex field): a weather region whose cloud field turns about its
// eye (WeatherRegion::vortex). Two parts, both shared by the march, the shadow map, the
// reprojection and the CPU reference:
//
// - The turn. The field turns at a rate that depends on the distance r from the eye: as a
//   solid body out to the eye wall's middle, then falling as r^-1.5 (a speed falling as
//   1/sqrt(r), slower than a free vortex's 1/r, so that the rain bands far out still move),
//   faded out with the region's strength. The noise at a point is read where the point was
//   turned back by the angle turned so far. A differential turn winds the noise ever tighter,
//   so each read's clock restarts every period and two reads half a period apart are
//   cross-faded (a flow map's two phases): the winding never exceeds one period's turn.
// - The look: an eye without cloud, a wall of cumulonimbus around it, and spiral rain bands of
//   the region's coverage trailing the turn beyond; the region's strength eases it into the
//   surrounding weather (columnWeather()). It is the still field's: the march reads weather and
//   noise alike where the turn brought a point from, so the whole storm turns (layerField()).
#ifndef CLOUDS_CLOUD_VORTEX_H
#define CLOUDS_CLOUD_VORTEX_H

#include "cloud_region_shape.h"

FX_SHADER_BEGIN(clouds::shader)

// Whether the pipeline has the vortex code (Settings::superstorms): the shaders'
// specialization constant; always in C++.
#ifdef __cplusplus
FX_INLINE bool vortexCompiledIn() {
  return true;
}
#else
bool vortexCompiledIn();
#endif

FX_INLINE bool hasVortex(IN(CloudUniforms) u) {
  return vortexCompiledIn() && u.vortexRegion != kNoVortex;
}

// The eye wall's middle: its distance (m) from the eye.
FX_INLINE float vortexWallMiddle(IN(WeatherRegionUniform) r) {
  return r.vortex.x + 0.5f * r.vortex.y;
}

// The field's rate of turn (rad/s, counter-clockwise seen from above) at `radius` m from the
// eye.
FX_INLINE float vortexTurnRate(float radius, IN(WeatherRegionUniform) r) {
  const float wall = vortexWallMiddle(r);
  const float beyond = wall / max(radius, wall);
  return r.vortex.z * beyond * sqrt(beyond) * regionStrength(radius, r);
}

// `d` (x, z) turned counter-clockwise seen from above (from +x towards -z) by `angle` radians.
FX_INLINE vec2 turnedCounterClockwise(vec2 d, float angle) {
  const float c = cos(angle);
  const float s = sin(angle);
  return vec2(c * d.x + s * d.y, c * d.y - s * d.x);
}

// Where the cloud at the camera-relative point `p` (x, z m) was `seconds` ago: turned back
// about the eye by the field's turn since. The noise is read there (the phase's clock), and
// the history finds the point's previous place there (the frame's interval).
FX_INLINE vec2 vortexTurnedBack(vec2 p, float seconds, IN(WeatherRegionUniform) r) {
  const vec2 eye = vec2(r.placement.x, r.placement.y);
  const vec2 d = p - eye;
  return eye + turnedCounterClockwise(d, -vortexTurnRate(length(d), r) * seconds);
}

// The superstorm's still look over the column at the camera-relative point `p` (x, z m): x
// coverage, y cloud type. `regionLook`: the region's (its coverage is the bands'). The march
// reads it, like the rest of the storm's field, where the turn brought a point from
// (layerField()), so the bands turn with the cloud.
FX_INLINE vec2 vortexLook(vec2 p, IN(WeatherRegionUniform) r, vec2 regionLook) {
  const vec2 d = p - vec2(r.placement.x, r.placement.y);
  const float radius = length(d);
  const float eye = r.vortex.x;
  const float width = r.vortex.y;
  const float middle = vortexWallMiddle(r);
  const float clear = smoothstep(0.7f * eye, eye, radius);
  const float wall = 1.0f - smoothstep(0.5f * width, width, abs(radius - middle));
  // Log spirals trailing the turn: along an arm the angle falls (for a counter-clockwise
  // storm) by kBandPitch radians per e-fold of the distance.
  const float kBandPitch = 1.2f;
  float band = 1.0f;
  if (r.vortex.w > 0.0f) {
    const vec2 direction = radius > 1.0f ? d / radius : vec2(1.0f, 0.0f);
    const float around = atan(-direction.y, direction.x);  // counter-clockwise from +x
    const float trailing = r.vortex.z < 0.0f ? -kBandPitch : kBandPitch;
    const float phase = r.vortex.w * (around + trailing * log(max(radius, 1.0f) / middle));
    band = 0.5f + 0.5f * cos(phase);
    band *= band;
  }
  const float bands = regionLook.x * (0.3f + 0.7f * band);
  // The wall is dense but not solid: the turning noise carves its face (at coverage 1 it would
  // be a still, opaque cylinder whose turn no one could see).
  const float kWallCoverage = 0.8f;
  return vec2(clear * max(kWallCoverage * wall, bands), mix(regionLook.y, 1.0f, wall));
}

FX_SHADER_END

#endif
