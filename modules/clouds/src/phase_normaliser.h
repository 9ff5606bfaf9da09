#pragma once
// The integral over the sphere of the silver-lining phase (shaders/cloud_math.h,
// silverLiningPhase() before its normalisation), so the uniforms can carry its inverse.

#include <array>

namespace clouds::detail {

// The lobes of one phase function: HG g values as the shader sees them (they are clamped there
// to +-0.99, and here the same way).
struct PhaseLobes {
  float forwardG = 0.0f;
  float backwardG = 0.0f;
  float backwardWeight = 0.0f;  // the mix's blend towards the backward lobe, [0, 1]
  float silverG = 0.0f;
  float silverIntensity = 0.0f;  // >= 0; 0 is the mix alone, whose integral is 1
};

// 2 pi x the integral over cos(theta) in [-1, 1] of max(mix of the lobes, silverIntensity x
// HG(silverG)), exact to about 1e-6: the HG lobes integrate in closed form between the points
// where the max changes sides, which are found by bisection.
double silverLiningPhaseIntegral(const PhaseLobes& lobes);

// 1 / silverLiningPhaseIntegral() for each of the 8 multiple-scattering octaves, octave n with
// every g scaled by eccentricityScale^n (octavePhases() in cloud_lighting.h). With the silver
// lining on this takes about 1.7 ms of CPU, and the uniforms are built every frame (twice with
// a shadow map) from settings that rarely change: the last answer is kept, per thread, and
// computed again only for other settings.
struct OctavePhaseSettings {
  PhaseLobes lobes;  // octave 0's
  float eccentricityScale = 1.0f;
};
std::array<float, 8> octavePhaseNormaliserInverses(const OctavePhaseSettings& settings);

}  // namespace clouds::detail
