#version 460
// The clouds' lightning glow at the trace resolution, after the temporal reconstruction (so a
// flash never enters a history: the frame after it ends is as if it never was); the upsample
// adds it, filtered, times each output pixel's cloud (1 - transmittance).
// Nubis Evolved's glow term (Schneider 2022: potential pow(1 - d / r, 12), less where the cloud
// is dense) and the flash's sky light (vkfx/lightning_light.h: the core's inverse square, the
// light that makes the whole deck flicker), per trace pixel at the clouds' transmittance-
// weighted depth along its ray. The
// local density of the seeds' pseudo-attenuation is that of the cloud the pixel sees into: its
// optical depth (at most 1: an opaque cloud shows its outer skin) over its depth span (twice
// the weighted depth past the front), exact for a thin uniform cloud.
// Inputs: 0 CloudUniforms, 1 the reconstructed trace image (packed: cloud_temporal.h), 2
// LightningUniforms. Output: 3 the glow per unit of cloud (RGBA16F, trace res).
#extension GL_GOOGLE_include_directive : require
#include "cloud_temporal.h"
#include "vkfx/lightning_light.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
#include "frame_uniforms.glsl"
layout(binding = kGlowTraceSamples, rgba32ui) uniform readonly uimage2D traceSamples;
// Indexed like frame_uniforms.glsl's block, for the same reason (the flash loop's bound).
layout(binding = kGlowFlashes, std140) uniform Lightning { LightningUniforms lightning[1]; };
layout(binding = kGlowOut, rgba16f) uniform writeonly image2D glowOut;

#include "cloud_march.h"

void main() {
  loadFrameUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, u.traceExtent))) return;
  const uvec4 packed = imageLoad(traceSamples, ivec2(pixel));
  const float transmittance = unpackCloudRadiance(packed).a;
  const vec2 depth = unpackCloudDepth(packed);
  vec3 glow = vec3(0.0f);
  if (depth.y > 0.0f && transmittance < 1.0f) {
    const uint slot = gl_NumWorkGroups.z - 1u;
    const vec3 ray = pixelRayDirection(vec2(pixel) + 0.5f, vec2(u.traceExtent), u);
    const vec3 cloud = ray * depth.y;  // camera-relative (m)
    const float span = max(2.0f * (depth.y - depth.x), 1.0f);
    const float opticalDepth = min(-log(max(transmittance, 1e-6f)), 1.0f);
    const float density = opticalDepth / span / max(u.extinctionPerMetre, 1e-12f);
    const float attenuation = 1.0f - saturate(density * 5.0f);
    for (uint i = 0u; i < lightning[slot].count.x; ++i) {
      const vec4 flash = lightning[slot].flash[2u * i];
      const float distance = length(cloud - flash.xyz);
      const float core = flashGlow(distance, flash.w) * attenuation;
      glow += lightning[slot].flash[2u * i + 1u].rgb * (core + flashSkyLight(distance, flash.w));
    }
  }
  imageStore(glowOut, ivec2(pixel), vec4(glow, 0.0f));
}
