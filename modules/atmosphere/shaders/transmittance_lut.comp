#version 460
// The transmittance LUT (Hillaire 2020, after Bruneton): for each texel a radius and a zenith
// cosine (atmosphere_model.h's parameterisation), the transmittance from there to the top of
// the atmosphere, exp(-optical depth), by the midpoint rule. Depends only on the atmosphere's
// parameters: recorded when they change, not every frame.
// Inputs: uniforms. Output: the LUT (RGBA16F, rgb transmittance).
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_types.h"
#include "atmosphere_model.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
#include "atmosphere_uniforms.glsl"
layout(binding = kBindingTarget, rgba16f) uniform writeonly image2D target;

vec3 sampleTransmittance(vec2 uv) { return vec3(1.0); }  // not read here
vec3 sampleMultiScattering(vec2 uv) { return vec3(0.0); }

void main() {
  loadUniforms();
  const uvec2 texel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(texel, u.transmittanceSize))) return;
  const AtmosphereModel a = modelOf(u);
  float r;
  float mu;
  transmittanceParams((vec2(texel) + 0.5) / vec2(u.transmittanceSize), a, r, mu);
  const vec3 depth = opticalDepthToTop(r, mu, u.transmittanceSamples, a);
  imageStore(target, ivec2(texel), vec4(exp(-depth), 1.0));
}
