#version 460
// The sky-view LUT (Hillaire 2020, section 5.3), every frame the camera's altitude or the sun
// moved: for each texel a view direction around the camera (its zenith angle, denser towards
// the horizon, and its azimuth from the sun's), the radiance of single scattering, with its
// Rayleigh and Mie phases, plus every further order from the multiple-scattering LUT, and where
// the direction hits the planet its sunlit ground seen through the air; for a sun of unit
// illuminance. The sky pass and the environment map read it.
// Inputs: uniforms, transmittance and multiple-scattering LUTs. Output: the LUT (RGBA16F).
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_types.h"
#include "atmosphere_model.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
#include "atmosphere_uniforms.glsl"
layout(binding = kBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kBindingMultiScattering) uniform sampler2D multiScatteringLut;
layout(binding = kBindingTarget, rgba16f) uniform writeonly image2D target;

vec3 sampleTransmittance(vec2 uv) { return textureLod(transmittanceLut, uv, 0.0).rgb; }
vec3 sampleMultiScattering(vec2 uv) { return textureLod(multiScatteringLut, uv, 0.0).rgb; }

void main() {
  loadUniforms();
  const uvec2 texel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(texel, u.skyViewSize))) return;
  const AtmosphereModel a = modelOf(u);
  const vec2 size = vec2(u.skyViewSize);
  float viewZenithCos;
  float lightViewCos;
  skyViewParams((vec2(texel) + 0.5) / size, u.horizonDip, size, viewZenithCos, lightViewCos);
  const vec3 direction = skyViewDirection(viewZenithCos, lightViewCos);
  const vec3 sun = sunInSkyViewFrame(u.sunDirection.y);
  const vec3 origin = vec3(0.0, u.cameraRadius, 0.0);
  const Scattering s = integrateScattering(origin, direction, sun, 1e9, u.skyViewSamples,
                                           kPhaseAtmosphere, 1u, float(u.multiScatteringSize),
                                           1u, a);
  imageStore(target, ivec2(texel), vec4(s.luminance, 1.0));
}
