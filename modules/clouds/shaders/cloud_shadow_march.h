// One texel of the cloud shadow map (fxcontracts/cloud_shadow.h), shared by the shadow-map shader
// and the CPU reference: the sun ray through a camera-relative point, marched up through the
// cloud layer in equal steps with the low-frequency shape alone (as the view march's light
// samples are), skipping weather cells that hold no cloud. It returns the ray's whole optical
// depth and the altitudes of its highest and lowest cloud, the Beer shadow map's texel.
//
// The ray is straight in the host's flat map (x, z, altitude): the map shadows receivers given
// in those coordinates, as a host's terrain is. Over 100 km the planet's curvature tilts the
// true sun direction by under a degree, which this ignores.
#ifndef CLOUDS_CLOUD_SHADOW_MARCH_H
#define CLOUDS_CLOUD_SHADOW_MARCH_H

#include "cloud_march.h"

FX_SHADER_BEGIN(clouds::shader)

struct ShadowColumn {
  float opticalDepth;  // of the whole ray through the layer
  // The optical depth counts each cloudy sample for its whole step, so the cloud spans from
  // the bottom of the lowest cloudy step to the top of the highest (exact for a uniform slab).
  // A ray without cloud spans the whole layer: filtering it with a cloudy neighbour then fades
  // the optical depth without dragging the neighbour's cloud down to the layer's bottom.
  float frontAltitude;  // m: top of the highest cloudy step; the layer top when none
  float backAltitude;   // m: bottom of the lowest cloudy step; the layer bottom when none
  float samples;        // density samples taken
};

// Most samples a shadow ray takes through hero clouds' boxes (at least a voxel apart).
const int kMaxHeroShadowSteps = 96;

// The hero clouds' share of a shadow column: the same ray through their boxes, in equal steps
// of at least a voxel, its optical depth added to the layer's (the integrals add) and its
// cloud's altitudes joined to the layer's span.
FX_INLINE void addHeroClouds(INOUT(ShadowColumn) column, vec3 base, vec3 light, float jitter,
                             IN(CloudUniforms) u) {
  const vec3 span = heroRaySpan(base, light, -kHeroFar);
  if (!(span.x < span.y)) return;
  const int steps = int(min(ceil((span.y - span.x) / span.z), float(kMaxHeroShadowSteps)));
  const float stepLength = (span.y - span.x) / float(steps);
  float tau = 0.0f;
  float lowest = kHeroFar;
  float highest = -kHeroFar;
  for (int k = 0; k < steps; ++k) {
    const float t = span.x + (float(k) + jitter) * stepLength;
    const HeroSample hero = heroField(base + light * t, u);
    column.samples += 1.0f;
    CLOUDS_WHEN(hero.sigmaT > 0.0f) {
      tau += hero.sigmaT * stepLength;
      lowest = min(lowest, span.x + float(k) * stepLength);
      highest = max(highest, span.x + float(k + 1) * stepLength);
    }
  }
  if (!(tau > 0.0f)) return;
  const float baseAltitude = u.cameraAltitudeMetres + base.y;
  const float front = baseAltitude + highest * light.y;
  const float back = baseAltitude + lowest * light.y;
  const bool layerHasCloud = column.opticalDepth > 0.0f;
  column.frontAltitude = layerHasCloud ? max(column.frontAltitude, front) : front;
  column.backAltitude = layerHasCloud ? min(column.backAltitude, back) : back;
  column.opticalDepth += tau;
}

// The sun ray through the camera-relative point `base` along `light` (unit, light.y > 0),
// sampled at `steps` equal steps from the layer's bottom to its top, each at `jitter` in
// [0, 1) of its step.
FX_INLINE ShadowColumn marchShadowColumn(vec3 base, vec3 light, uint steps, float jitter,
                                         uint emptySpace, IN(CloudUniforms) u) {
  ShadowColumn column;
  column.opticalDepth = 0.0f;
  column.frontAltitude = u.layerTopMetres;
  column.backAltitude = u.layerBottomMetres;
  column.samples = 0.0f;
  const float baseAltitude = u.cameraAltitudeMetres + base.y;
  // Distances along the ray from `base` to the layer's bottom and top.
  const float start = (u.layerBottomMetres - baseAltitude) / light.y;
  const float end = (u.layerTopMetres - baseAltitude) / light.y;
  const float stepLength = (end - start) / float(max(steps, 1u));
  const float stepRise = stepLength * light.y;  // altitude gained per step
  const vec2 origin = vec2(base.x, base.z);
  int lowest = int(steps);  // the lowest and highest cloudy steps
  int highest = -1;
  int k = 0;  // the step whose sample comes next
  for (int i = 0; i < int(steps) + kMaxSkips; ++i) {
    if (k >= int(steps)) break;
    const float t = start + (float(k) + jitter) * stepLength;
    const float altitude = baseAltitude + t * light.y;
    if (emptySpace != 0u) {
      // The ray only climbs: an empty cell (or one whose tallest cloud is below) is skipped
      // to the first step whose sample lies beyond it.
      const float skipTo = emptySpaceSkip(origin, t, light, altitude, u);
      if (skipTo > t) {
        // (Clamped before the conversion: a vertical ray skips to "infinity".)
        k = int(min(ceil((skipTo - start) / stepLength - jitter), float(steps)));
        continue;
      }
    }
    const vec3 p = base + light * t;
    // The layer alone: the hero clouds, which may stand beyond it, are marched after it.
    const FieldSample field = layerField(vec3(p.x, 0.0f, p.z), altitude, 0.0f, 0.0f, 0u, u);
    column.samples += 1.0f;
    CLOUDS_WHEN(field.sigmaT > 0.0f) {
      column.opticalDepth += field.sigmaT * stepLength;
      lowest = min(lowest, k);
      highest = max(highest, k);
    }
    ++k;
  }
  if (highest >= lowest) {
    column.frontAltitude = u.layerBottomMetres + float(highest + 1) * stepRise;
    column.backAltitude = u.layerBottomMetres + float(lowest) * stepRise;
  }
  if (heroCloudCount() > 0u) {  // a plain if (cloud_march.h's kHeroCompiledOut)
    addHeroClouds(column, base, light, jitter, u);
  }
  return column;
}

// Texel `texel` of the cascade a dispatch makes with `c`: its ray through the camera-relative
// point at the texel's centre, jittered by a hash of the texel's place on the world grid (so
// the map does not shimmer as the cascade scrolls).
FX_INLINE ShadowColumn marchShadowTexel(IN(ShadowMapConstants) c, uvec2 texel, uint emptySpace,
                                        IN(CloudUniforms) u) {
  const float size = c.light.w;
  const vec3 base = vec3(c.axisU) * (c.axisU.w + float(texel.x) * size) +
                    vec3(c.axisV) * (c.axisV.w + float(texel.y) * size);
  const float jitter = hashCell(ivec3(c.worldTexel + ivec2(texel), int(c.cascade)), 4099u).x;
  return marchShadowColumn(base, vec3(c.light), c.steps, jitter, emptySpace, u);
}

// The light direction a shadow map is made with: the sun, raised to kShadowMinSunSine of
// elevation when lower (a sun at the horizon would make every ray through the layer endless;
// below a few degrees the air has already taken nearly all of its light).
const float kShadowMinSunSine = 0.0349f;  // sin(2 degrees)

FX_INLINE vec3 shadowLightDirection(vec3 sun) {
  const vec2 horizontal = vec2(sun.x, sun.z);
  const float length2 = dot(horizontal, horizontal);
  if (sun.y >= kShadowMinSunSine || length2 < 1e-12f) {
    return sun.y >= kShadowMinSunSine ? sun : vec3(0.0f, 1.0f, 0.0f);
  }
  const float cosine = sqrt(1.0f - kShadowMinSunSine * kShadowMinSunSine);
  const vec2 azimuth = horizontal / sqrt(length2);
  return vec3(azimuth.x * cosine, kShadowMinSunSine, azimuth.y * cosine);
}

FX_SHADER_END

#endif
