// Cloud-model math shared by the GPU shaders and the CPU reference: remapping, phase
// functions, transmittance, energy-conserving integration and planet-scale ray/sphere tests.
// References: Schneider & Vos 2017 (Nubis, remap); Henyey & Greenstein 1941; Hillaire 2016
// "Physically based sky, atmosphere and cloud rendering in Frostbite" (integration).
#ifndef CLOUDS_CLOUD_MATH_H
#define CLOUDS_CLOUD_MATH_H

#include "fxcontracts/shader_interop.h"

// Runs the following statement or block only when `condition` holds, as a loop of 0 or 1 trips:
// lavapipe executes the body of an `if` whenever it is reached, even when no lane takes it.
// Its counter is named after the line, so that one may nest in another.
#define CLOUDS_WHEN_JOIN_(a, b) a##b
#define CLOUDS_WHEN_NAME_(line) CLOUDS_WHEN_JOIN_(whenOnce_, line)
#define CLOUDS_WHEN(condition)                                                                   \
  for (int CLOUDS_WHEN_NAME_(__LINE__) = 0; CLOUDS_WHEN_NAME_(__LINE__) < ((condition) ? 1 : 0); \
       ++CLOUDS_WHEN_NAME_(__LINE__))

FX_SHADER_BEGIN(clouds::shader)

const float kPi = 3.14159265358979f;
// g beyond this makes HG a delta peak whose float evaluation overflows (g = 1 gives 0/0).
const float kMaxPhaseG = 0.99f;

FX_INLINE float saturate(float x) {
  return clamp(x, 0.0f, 1.0f);
}

// Maps `value` from [oldMin, oldMax] to [newMin, newMax] (no clamping), as in Nubis. A
// degenerate source range maps everything to newMin instead of dividing by zero.
FX_INLINE float remap(float value, float oldMin, float oldMax, float newMin, float newMax) {
  const float range = oldMax - oldMin;
  const float t = abs(range) > 1e-7f ? (value - oldMin) / range : 0.0f;
  return newMin + t * (newMax - newMin);
}

FX_INLINE float remapClamped(float value, float oldMin, float oldMax, float newMin, float newMax) {
  return mix(newMin, newMax, saturate(remap(value, oldMin, oldMax, 0.0f, 1.0f)));
}

// Henyey-Greenstein phase function, normalised over the sphere (units 1/sr). g is clamped to
// [-0.99, 0.99] so g = +-1 cannot produce 0/0, and the base is kept positive.
FX_INLINE float henyeyGreenstein(float cosTheta, float g) {
  const float gc = clamp(g, -kMaxPhaseG, kMaxPhaseG);
  const float c = clamp(cosTheta, -1.0f, 1.0f);
  const float g2 = gc * gc;
  const float denominator = max(1.0f + g2 - 2.0f * gc * c, 1e-6f);
  return (1.0f - g2) / (4.0f * kPi * denominator * sqrt(denominator));
}

// Two HG lobes blended so the result stays normalised: a strong forward lobe gives the silver
// lining towards the sun, a weak backward lobe keeps clouds facing away from the sun lit.
FX_INLINE float dualLobePhase(float cosTheta, float forwardG, float backwardG, float blend) {
  const float w = saturate(blend);
  return mix(henyeyGreenstein(cosTheta, forwardG), henyeyGreenstein(cosTheta, backwardG), w);
}

// The seeds' silver lining (Schneider 2017): where a sharp forward lobe, silverIntensity x
// HG(silverG), is brighter than the two lobes' mix, it replaces it (max()), which lights thin
// cloud around the sun without darkening cloud 90 degrees away as a stronger forward g would.
// The max gains energy; `normaliserInverse` (1 / its integral over the sphere, computed on the
// CPU: phase_normaliser.cpp) gives it back, so the phase integrates to 1 and the white furnace
// holds. silverIntensity 0 (normaliserInverse 1) is the mix alone.
FX_INLINE float silverLiningPhase(float cosTheta, float forwardG, float backwardG, float blend,
                                  float silverG, float silverIntensity, float normaliserInverse) {
  const float lobes = dualLobePhase(cosTheta, forwardG, backwardG, blend);
  const float silver = max(silverIntensity, 0.0f) * henyeyGreenstein(cosTheta, silverG);
  return max(lobes, silver) * normaliserInverse;
}

// Beer-Lambert transmittance for an optical depth (>= 0). exp(-x) of a huge x is 0, never NaN.
FX_INLINE float beerLambert(float opticalDepth) {
  return exp(-max(opticalDepth, 0.0f));
}

// (1 - exp(-sigma * d)) / sigma, the in-scattering weight of a homogeneous step of length d
// (Hillaire 2016), written so sigma = 0 gives d instead of 0/0.
FX_INLINE float stepScatteringWeight(float sigmaT, float stepLength) {
  const float x = max(sigmaT, 0.0f) * stepLength;
  if (x < 1e-4f) return stepLength * (1.0f - 0.5f * x);
  return (1.0f - exp(-x)) / max(sigmaT, 1e-30f);
}

// Distance along a unit ray from a point at `altitude` above a planet of radius `radius` to
// the sphere at `sphereAltitude` (both altitudes above the planet surface), given the cosine
// of the ray with the local up. The altitude-difference form keeps float precision at planet
// scale (a textbook |o - c|^2 - r^2 loses metres near the horizon). Returns the near and far
// roots in x and y; y < 0 when the sphere is not hit at all (x = y = -1).
FX_INLINE vec2 raySphere(float altitude, float cosZenith, float sphereAltitude, float radius) {
  const float distanceToCentre = radius + altitude;
  const float b = distanceToCentre * cosZenith;  // dot(origin - centre, direction)
  // c = |origin - centre|^2 - r^2, from the altitude difference.
  const float c = (altitude - sphereAltitude) * (2.0f * radius + altitude + sphereAltitude);
  const float discriminant = b * b - c;
  if (discriminant < 0.0f) return vec2(-1.0f, -1.0f);
  const float s = sqrt(discriminant);
  // Stable roots: q has the sign of -b so no cancellation; t0 * t1 = c.
  const float q = b > 0.0f ? -(b + s) : (s - b);
  const float t0 = q;
  const float t1 = abs(q) > 1e-30f ? c / q : 0.0f;
  return vec2(min(t0, t1), max(t0, t1));
}

// Halton radical inverse, base 2 or 3 (jitter sequences).
FX_INLINE float halton(uint index, uint base) {
  float f = 1.0f;
  float result = 0.0f;
  uint i = index;
  for (int k = 0; k < 16 && i > 0u; ++k) {
    f /= float(base);
    result += f * float(i % base);
    i /= base;
  }
  return result;
}

// Where the rays of one round of refreshes start in their first step, in [0, 1): a Halton
// sequence over the rounds (a pixel is refreshed once per round of k x k frames). With temporal
// upsampling a trace pixel's refreshes take turns over the `streams` output pixels it covers
// (round % streams picks the output pixel, round / streams counts its visits), and each output
// pixel keeps the mean of its own samples: so each runs the sequence over its own visits,
// shifted by its own point of the same sequence, and both an output pixel's samples and each
// round of visits are spread over [0, 1). (One sequence over the rounds gave an output pixel
// the points 4 indices apart, whose two lowest bits agree: all its samples started within
// [1/2, 3/4) of a step, and their mean kept the error of where they started.) `streams` 1: one
// sequence over the rounds. The first round starts mid-step: a single frame is a midpoint rule.
FX_INLINE float refreshStartOffset(uint round, uint streams) {
  const uint s = max(streams, 1u);
  return fract(halton((round / s) % 64u, 2u) + halton(round % s, 2u) + 0.5f);
}

// 2x2 Bayer threshold in [0, 1) for a pixel: (0, 0) 1/8, (1, 1) 3/8, (1, 0) 5/8, (0, 1) 7/8.
FX_INLINE float bayer2x2(uvec2 pixel) {
  const uint v = (pixel.x ^ pixel.y) & 1u;
  const uint index = (v << 1u) | (pixel.y & 1u);
  return (float(index) + 0.5f) / 4.0f;
}

// 4x4 Bayer threshold in [0, 1) for a pixel.
FX_INLINE float bayer4x4(uvec2 pixel) {
  const uint x = pixel.x & 3u;
  const uint y = pixel.y & 3u;
  // Interleave the bits of x ^ y and y: the classic recursive Bayer construction.
  const uint v = x ^ y;
  const uint index = ((v & 1u) << 3u) | ((y & 1u) << 2u) | ((v & 2u) >> 0u) | ((y & 2u) >> 1u);
  return (float(index) + 0.5f) / 16.0f;
}

FX_SHADER_END

#endif
