#version 460
// God rays, first pass (vkfx/god_rays.h): the occlusion image at a quarter of the render
// extent per axis. Each texel is the mean over its 4 x 4 pixels of the clouds' transmittance
// where the host's depth is the far plane (sky), 0 on the host's geometry: what the air towards
// each pixel shows of the sun's light, before the radial blur.
// Inputs: 0 the clouds' radiance output (a: transmittance), 1 the host's depth (sampled; with
// no depth every pixel is sky); push constants GodRayOcclusionConstants. Output: 2 the
// occlusion image (R32F).
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;

layout(binding = kGodRayRadiance, rgba16f) uniform readonly image2D cloudRadiance;
layout(binding = kGodRayHostDepth) uniform sampler2D hostDepth;
layout(binding = kGodRayOcclusionOut, r32f) uniform writeonly image2D occlusion;
layout(push_constant) uniform Constants { GodRayOcclusionConstants c; };

void main() {
  const uvec2 texel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(texel, c.maskExtent))) return;
  const float farPlane = c.reversedZ != 0u ? 0.0f : 1.0f;
  float clear = 0.0f;
  float pixels = 0.0f;
  for (uint y = 0u; y < kGodRayDownsample; ++y) {
    for (uint x = 0u; x < kGodRayDownsample; ++x) {
      const uvec2 pixel = texel * kGodRayDownsample + uvec2(x, y);
      if (any(greaterThanEqual(pixel, c.renderExtent))) continue;
      const float transmittance = imageLoad(cloudRadiance, ivec2(pixel)).a;
      const float depth = c.hasDepth != 0u ? texelFetch(hostDepth, ivec2(pixel), 0).r : farPlane;
      clear += depth == farPlane ? transmittance : 0.0f;
      pixels += 1.0f;
    }
  }
  imageStore(occlusion, ivec2(texel), vec4(clear / max(pixels, 1.0f)));
}
