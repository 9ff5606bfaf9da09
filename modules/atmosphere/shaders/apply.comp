#version 460
// The atmosphere over the host's colour, in place, at the output resolution: where the host's
// depth is the far plane (or there is no depth: kSpecHasDepth 0) the sky (sky_radiance.glsl)
// and the sun's disc with limb darkening seen through the air (clamped to maxRadiance, a
// half-float target's range); elsewhere the aerial perspective at the pixel's distance,
// colour = colour * transmittance + in-scattering (Hillaire 2020; within the first slice it
// fades from none at the camera). Everything times the sun's illuminance.
// Inputs: uniforms, the transmittance and sky-view LUTs, the aerial-perspective froxels, the
// host's depth. Output: the host's colour (RGBA16F storage, GENERAL).
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_types.h"
#include "atmosphere_model.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(constant_id = kSpecHasDepth) const uint kHasDepth = 1u;
#include "atmosphere_uniforms.glsl"
layout(binding = kBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kBindingSkyView) uniform sampler2D skyViewLut;
layout(binding = kBindingAerialPerspective) uniform sampler3D aerialPerspective;
layout(binding = kBindingHostDepth) uniform sampler2D hostDepth;
layout(binding = kBindingTarget, rgba16f) uniform image2D hostColor;

vec3 sampleTransmittance(vec2 uv) { return textureLod(transmittanceLut, uv, 0.0).rgb; }
vec3 sampleMultiScattering(vec2 uv) { return vec3(0.0); }
#include "sky_radiance.glsl"

vec3 sky(vec3 direction, AtmosphereModel a) {
  vec3 radiance = skyRadiance(direction, a);
  const float disc = sunDiscRadiance(dot(direction, u.sunDirection), u.sunAngularRadius);
  if (disc > 0.0) radiance += sunTransmittance(u.cameraRadius, direction.y, a) * disc;
  return min(radiance * u.sunIlluminance, vec3(u.maxRadiance));
}

void main() {
  loadUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, u.outputExtent))) return;
  const AtmosphereModel a = modelOf(u);
  const vec2 centre = vec2(pixel) + 0.5;
  const vec3 direction = viewDirection(centre, vec2(u.outputExtent));
  const bool reversed = (u.flags & kFlagReversedZ) != 0u;
  float depth = reversed ? 0.0 : 1.0;
  if (kHasDepth != 0u) depth = texelFetch(hostDepth, ivec2(pixel), 0).r;
  const bool isSky = reversed ? depth <= 0.0 : depth >= 1.0;
  if (isSky) {
    imageStore(hostColor, ivec2(pixel), vec4(sky(direction, a), 1.0));
    return;
  }
  // The distance to the geometry along the pixel's ray.
  const vec2 ndc = centre / vec2(u.outputExtent) * 2.0 - 1.0;
  const vec4 view = u.inverseProjection * vec4(ndc, depth, 1.0);
  const float distance = length(view.xyz / view.w);
  const float w = sqrt(distance / u.aerialPerspectiveRange);
  const float slice = w * float(u.aerialPerspectiveSize.z) - 0.5;
  vec4 haze = textureLod(aerialPerspective, vec3(centre / vec2(u.outputExtent), min(w, 1.0)), 0.0);
  // Nearer than the first slice's centre: from no haze at the camera to the first slice.
  const float weight = clamp(slice * 2.0 + 1.0, 0.0, 1.0);
  haze = vec4(haze.rgb * weight, mix(1.0, haze.a, weight));
  const vec4 colour = imageLoad(hostColor, ivec2(pixel));
  imageStore(hostColor, ivec2(pixel),
             vec4(colour.rgb * haze.a + haze.rgb * u.sunIlluminance, colour.a));
}
