#version 460
// The multiple-scattering LUT (Hillaire 2020, section 5.5): for a point at some altitude and a
// sun zenith angle, the luminance of every scattering order past the first
// (atmosphere_model.h: multipleScatteringTexel). Depends only on the parameters.
// Inputs: uniforms, the transmittance LUT. Output: the LUT (RGBA16F, rgb Psi).
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_types.h"
#include "atmosphere_model.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
#include "atmosphere_uniforms.glsl"
layout(binding = kBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kBindingTarget, rgba16f) uniform writeonly image2D target;

vec3 sampleTransmittance(vec2 uv) { return textureLod(transmittanceLut, uv, 0.0).rgb; }
vec3 sampleMultiScattering(vec2 uv) { return vec3(0.0); }  // this is what is being made

void main() {
  loadUniforms();
  const uvec2 texel = gl_GlobalInvocationID.xy;
  const uint size = u.multiScatteringSize;
  if (any(greaterThanEqual(texel, uvec2(size)))) return;
  const vec2 uv = (vec2(texel) + 0.5) / float(size);
  const vec3 psi = multipleScatteringTexel(uv, float(size), u.multiScatteringDirections,
                                           u.multiScatteringSamples, modelOf(u));
  imageStore(target, ivec2(texel), vec4(psi, 1.0));
}
