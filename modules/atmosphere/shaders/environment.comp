#version 460
// The sky around the camera as a small equirectangular radiance map (kEnvironmentWidth x
// kEnvironmentHeight, u = azimuth from +X towards +Z, v = 0 at the zenith, 0.5 at the horizon,
// 1 at the nadir), for effects lit by the sky (the clouds' ambient); below the horizon the air
// in front of the ground plus the sunlit ground (its albedo) seen through it. One workgroup,
// which also measures the map for the host (SkyLighting: hemisphere means by solid angle, a
// zenith cap and a horizon band), read back once the frame completed (auto-exposure, ambient).
// Inputs: uniforms, the transmittance and sky-view LUTs. Outputs: the map (RGBA16F), the
// SkyLighting buffer.
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_types.h"
#include "atmosphere_model.h"

layout(local_size_x = kEnvironmentLanes) in;
#include "atmosphere_uniforms.glsl"
layout(binding = kBindingTransmittance) uniform sampler2D transmittanceLut;
layout(binding = kBindingSkyView) uniform sampler2D skyViewLut;
layout(binding = kBindingTarget, rgba16f) uniform writeonly image2D target;
layout(binding = kBindingSkyLighting, std430) buffer Lighting { SkyLighting lighting; };

vec3 sampleTransmittance(vec2 uv) { return textureLod(transmittanceLut, uv, 0.0).rgb; }
vec3 sampleMultiScattering(vec2 uv) { return vec3(0.0); }
#include "sky_radiance.glsl"

// Per lane: radiance x solid-angle weight (rgb) and the weight (a), for each region.
shared vec4 upperSum[kEnvironmentLanes];
shared vec4 zenithSum[kEnvironmentLanes];
shared vec4 horizonSum[kEnvironmentLanes];
shared vec4 lowerSum[kEnvironmentLanes];

void main() {
  loadUniforms();
  const AtmosphereModel a = modelOf(u);
  const uint lane = gl_LocalInvocationID.x;
  const uint texels = kEnvironmentWidth * kEnvironmentHeight;
  vec4 upper = vec4(0.0), zenith = vec4(0.0), horizon = vec4(0.0), lower = vec4(0.0);
  for (uint index = lane; index < texels; index += kEnvironmentLanes) {
    const uvec2 texel = uvec2(index % kEnvironmentWidth, index / kEnvironmentWidth);
    const vec2 uv = (vec2(texel) + 0.5) / vec2(kEnvironmentWidth, kEnvironmentHeight);
    const float azimuth = 2.0 * kPi * uv.x;
    const float elevation = kPi * (0.5 - uv.y);
    const vec3 direction =
        vec3(cos(azimuth) * cos(elevation), sin(elevation), sin(azimuth) * cos(elevation));
    const vec3 radiance = skyRadiance(direction) * u.sunIlluminance;
    imageStore(target, ivec2(texel), vec4(radiance, 1.0));
    // An equirectangular texel's solid angle goes with cos(elevation).
    const vec4 weighted = vec4(radiance, 1.0) * cos(elevation);
    if (elevation >= 0.0) upper += weighted;
    if (elevation >= kPi / 3.0) zenith += weighted;
    if (elevation >= 0.0 && elevation <= kPi / 18.0) horizon += weighted;
    if (elevation < 0.0) lower += weighted;
  }
  upperSum[lane] = upper;
  zenithSum[lane] = zenith;
  horizonSum[lane] = horizon;
  lowerSum[lane] = lower;
  barrier();
  for (uint stride = kEnvironmentLanes / 2u; stride > 0u; stride >>= 1u) {
    if (lane < stride) {
      upperSum[lane] += upperSum[lane + stride];
      zenithSum[lane] += zenithSum[lane + stride];
      horizonSum[lane] += horizonSum[lane + stride];
      lowerSum[lane] += lowerSum[lane + stride];
    }
    barrier();
  }
  if (lane == 0u) {
    const vec3 meanUpper = upperSum[0].rgb / max(upperSum[0].a, 1e-6);
    lighting.meanUpper = vec4(meanUpper, dot(meanUpper, vec3(0.2126, 0.7152, 0.0722)));
    lighting.zenith = vec4(zenithSum[0].rgb / max(zenithSum[0].a, 1e-6), 0.0);
    lighting.horizon = vec4(horizonSum[0].rgb / max(horizonSum[0].a, 1e-6), 0.0);
    lighting.lower = vec4(lowerSum[0].rgb / max(lowerSum[0].a, 1e-6), 0.0);
  }
}
