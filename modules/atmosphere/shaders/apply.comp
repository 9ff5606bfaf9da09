#version 460
// The atmosphere over the host's colour, in place, at the output resolution: where the host's
// depth is the far plane (or there is no depth: kSpecHasDepth 0) the sky (sky_radiance.glsl)
// and the sun's disc with limb darkening seen through the air (clamped to maxRadiance, a
// half-float target's range); elsewhere the aerial perspective at the pixel's distance
// (fxcontracts/aerial_perspective.glsl), colour = colour * transmittance + in-scattering (Hillaire
// 2020). Everything times the sun's illuminance.
// Inputs: uniforms, the sky-view LUT, the aerial-perspective froxels, the host's depth.
// Output: the host's colour (RGBA16F storage, GENERAL).
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_types.h"
#include "atmosphere_model.h"
#include "fxcontracts/aerial_perspective.glsl"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(constant_id = kSpecHasDepth) const uint kHasDepth = 1u;
// (Constants, not uniforms: without the host's depth every pixel is sky, and the haze is
// compiled out; a uniform would leave both paths in for lavapipe to run.)
layout(constant_id = kSpecReversedZ) const uint kReversedZ = 1u;
#include "atmosphere_uniforms.glsl"
layout(binding = kBindingSkyView) uniform sampler2D skyViewLut;
layout(binding = kBindingAerialPerspective) uniform sampler3D aerialPerspective;
layout(binding = kBindingHostDepth) uniform sampler2D hostDepth;
layout(binding = kBindingTarget, rgba16f) uniform image2D hostColor;

// Not read here (the model's integrals are not used), but every shader defines them.
vec3 sampleTransmittance(vec2 uv) { return vec3(1.0); }
vec3 sampleMultiScattering(vec2 uv) { return vec3(0.0); }
#include "sky_radiance.glsl"

// Every pixel pays for every line here (lavapipe runs both sides of a branch), so the pass is
// straight-line: the sky and the haze for each pixel, then a select.
void main() {
  loadUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, u.outputExtent))) return;
  const bool reversed = kReversedZ != 0u;
  const float far = reversed ? 0.0 : 1.0;
  float depth = far;
  // (A specialization constant: without the host's depth the fetch is compiled out; it must
  // be, the placeholder bound instead is one texel.)
  if (kHasDepth != 0u) depth = texelFetch(hostDepth, ivec2(pixel), 0).r;
  const vec2 uv = (vec2(pixel) + 0.5) / vec2(u.outputExtent);
  const vec4 ndc = vec4(uv * 2.0 - 1.0, depth, 1.0);
  const vec4 ray = u.clipToWorldRay * vec4(ndc.xy, far, 1.0);
  const vec3 direction = normalize(ray.xyz);

  // The aerial perspective at the geometry's distance.
  const vec4 view = u.inverseProjection * ndc;
  const float distance = length(view.xyz) / abs(view.w);
  const vec4 haze = aerialPerspectiveAt(aerialPerspective, uv, distance, u.aerialPerspectiveRange,
                                        float(u.aerialPerspectiveSize.z));
  const vec4 colour = imageLoad(hostColor, ivec2(pixel));
  const vec3 hazed = colour.rgb * haze.a + haze.rgb * u.sunIlluminance;

  const bool isSky = reversed ? depth <= 0.0 : depth >= 1.0;
  const vec4 result = isSky ? vec4(skyWithSun(direction), 1.0) : vec4(hazed, colour.a);
  imageStore(hostColor, ivec2(pixel), result);
}
