// The water's surface (a lake or sea at one level), shared by its fragment stage
// (water_fragment.glsl) and the C++ tests: ripples that a pixel resolves as a normal and the rest
// as roughness, Fresnel's reflection, the sun's glint off the ripples, and the share of the bed
// the water lets through. Radiometry in the scene's units (kcd/m^2 and klx); lengths in metres.
#ifndef SAMPLE_SHADERS_WATER_SURFACE_H
#define SAMPLE_SHADERS_WATER_SURFACE_H

#include "interop.h"
#ifdef __cplusplus
#include <cmath>
#endif

SHADER_NAMESPACE_BEGIN

// How far the surface reaches from the camera each way (m): past the horizon of any altitude
// the aircraft flies at (its ceiling's horizon is about 300 km away on the round planet, but the
// haze has hidden the sea long before 100 km).
const float kWaterReachMetres = 100000.0f;

// Fresnel's reflectance of water (refractive index 1.33: 0.02 head on) for the cosine between
// the view and the surface's normal (Schlick's approximation).
SHADER_INLINE float waterFresnel(float cosine) {
  const float f0 = 0.02f;
  const float m = 1.0f - clamp(cosine, 0.0f, 1.0f);
  const float m2 = m * m;
  return f0 + (1.0f - f0) * (m2 * m2 * m);
}

// The ripples: eight wind waves, wavelengths 12 m down to 0.8 m, their directions spread within
// 70 degrees either side of the wind's (+x) by the golden angle, so that no two run alike and
// their crests cross rather than line up into stripes.
const int kWaterWaves = 8;
SHADER_INLINE float waterWavelength(int wave) {
  return 12.0f * pow(0.68f, float(wave));
}
SHADER_INLINE vec2 waterWaveDirection(int wave) {
  const float angle = 1.2f * (2.0f * fract(0.618034f * float(wave) + 0.5f) - 1.0f);  // radians
  return vec2(cos(angle), sin(angle));
}
// How fast a wave's phase turns (rad/s): deep water's dispersion, omega = sqrt(g k).
SHADER_INLINE float waterAngularFrequency(int wave) {
  return sqrt(9.81f * 6.28318531f / waterWavelength(wave));
}

// Each wave's phase at the camera's (x, z) `cameraXz` (m) at time `seconds` of the game clock,
// wrapped to [0, 2 pi): made on the CPU in double precision, so that the GPU works with
// camera-relative positions and the ripples run on unchanged after any uptime and at any distance
// from the origin.
#ifdef __cplusplus
struct WaterPhases {
  vec4 first;   // waves 0 to 3
  vec4 second;  // waves 4 to 7
  float operator[](int wave) const { return wave < 4 ? first[wave] : second[wave - 4]; }
};
inline WaterPhases waterPhasesAt(glm::dvec2 cameraXz, double seconds) {
  const double kTwoPi = 6.283185307179586;
  WaterPhases phases{vec4(0.0f), vec4(0.0f)};
  for (int i = 0; i < kWaterWaves; ++i) {
    const glm::dvec2 direction(waterWaveDirection(i));
    const double k = kTwoPi / double(waterWavelength(i));
    const double phase =
        k * glm::dot(direction, cameraXz) - double(waterAngularFrequency(i)) * seconds;
    const float wrapped = float(phase - kTwoPi * std::floor(phase / kTwoPi));
    (i < 4 ? phases.first : phases.second)[i % 4] = wrapped;
  }
  return phases;
}
#endif

// The ripples at `relativeXz` (m from the camera), each wave at its phase there (waves 0 to 3 in
// `phases`, 4 to 7 in `phasesHigh`: waterPhasesAt()).
// Returns xy the slope (dh/dx, dh/dz) of the waves the pixel resolves, z the variance of the
// slope of those it does not: a wave fades out of the normal while the pixel's footprint (m)
// grows from a sixteenth to a quarter of its wavelength, and its slope's variance goes into the
// roughness instead, so the far water glints as widely as its ripples would, without aliasing.
SHADER_INLINE vec3 waterRipples(vec2 relativeXz, vec4 phases, vec4 phasesHigh,
                                float footprintMetres) {
  const float kTwoPi = 6.28318531f;
  const float steepness = 0.05f;  // a wave's greatest slope (k times its height amplitude)
  vec3 ripples = vec3(0.0f, 0.0f, 0.0f);
  for (int i = 0; i < kWaterWaves; ++i) {
    const float wavelength = waterWavelength(i);
    const vec2 direction = waterWaveDirection(i);
    const float phase =
        kTwoPi / wavelength * (direction.x * relativeXz.x + direction.y * relativeXz.y) +
        (i < 4 ? phases[i] : phasesHigh[i - 4]);
    const float resolved =
        1.0f - smoothstep(wavelength / 16.0f, wavelength / 4.0f, footprintMetres);
    const float slope = steepness * cos(phase);
    ripples.x += resolved * slope * direction.x;
    ripples.y += resolved * slope * direction.y;
    // A sinusoid's slope has variance amplitude^2 / 2.
    ripples.z += (1.0f - resolved) * 0.5f * steepness * steepness;
  }
  return ripples;
}

// The normal of a surface of height h(x, z) with slope (dh/dx, dh/dz).
SHADER_INLINE vec3 waterNormal(vec2 slope) {
  return normalize(vec3(-slope.x, 1.0f, -slope.y));
}

// The sun's glint: the radiance the surface reflects towards the viewer per unit of the sun's
// illuminance (1/sr), a Beckmann microfacet lobe (slope variance `roughness2`: the ripples the
// pixel does not resolve, plus calm water's own) with Fresnel's reflectance at the half vector.
// `normal`, `toViewer`, `toSun` are unit vectors; Smith's shadowing is left out (it matters only
// at grazing sun and view, where the haze dims the glint anyway).
SHADER_INLINE float waterGlint(vec3 normal, vec3 toViewer, vec3 toSun, float roughness2) {
  const float kPi = 3.14159265f;
  const float nl = dot(normal, toSun);
  const float nv = dot(normal, toViewer);
  if (nl <= 0.0f || nv <= 0.0f) return 0.0f;
  const vec3 h = normalize(toViewer + toSun);
  const float nh = max(dot(normal, h), 1e-4f);
  const float m2 = max(roughness2, 1e-4f) + 0.002f;
  const float nh2 = nh * nh;
  const float tan2 = (1.0f - nh2) / nh2;
  const float beckmann = exp(-tan2 / m2) / (kPi * m2 * nh2 * nh2);
  // f = D F / (4 nl nv); the radiance is f times the illuminance times nl.
  return beckmann * waterFresnel(dot(toViewer, h)) / (4.0f * nv);
}

// The share of the light from the bed that the water lets through towards a viewer looking
// down at `cosine` from the vertical (its path through the water grows as 1 / cosine):
// `clarity` is the share seen straight down.
SHADER_INLINE float waterBedShare(float clarity, float cosine) {
  if (clarity <= 0.0f) return 0.0f;
  return pow(clarity, 1.0f / max(cosine, 1e-4f));
}

// How far from the camera (m, horizontally) the bed can still show: beyond it the water lets
// through less than 1/255 of the bed's light (waterBedShare() at the view's cosine there), so
// the water there can be drawn before the terrain and hide the bed, which then costs no shading.
// `heightMetres` is the camera's height above the water; at or below it (no view from above),
// and with clear water (clarity 1), everywhere.
SHADER_INLINE float waterBedReachMetres(float clarity, float heightMetres) {
  if (clarity <= 0.0f) return 0.0f;
  if (clarity >= 1.0f || heightMetres <= 0.0f) return kWaterReachMetres;
  // clarity^(distance / height) < 1/255 for distance > height log2(255) / -log2(clarity).
  const float distance = heightMetres * (7.99435f / -log2(clarity));
  const float horizontal = sqrt(max(distance * distance - heightMetres * heightMetres, 0.0f));
  return min(horizontal, kWaterReachMetres);
}

SHADER_NAMESPACE_END

#endif
