#version 460
// God rays, second pass (vkfx/god_rays.h): the mask. Each texel averages the occlusion image
// at GodRayParameters' samples on its way towards the sun on screen, their weights decaying
// (Mitchell 2007): 1 where the air along its pixels' rays sees the sun past everything on
// screen, lower in the shadows clouds and mountains cast through the air.
// Inputs: 0 the occlusion image (sampled, linear, clamped); push constants GodRayParameters.
// Output: 1 the mask (R32F, the module's Outputs::godRayMask).
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;

layout(binding = kGodRayOcclusion) uniform sampler2D occlusion;
layout(binding = kGodRayMaskOut, r32f) uniform writeonly image2D mask;
layout(push_constant) uniform Constants { GodRayParameters p; };

float fetchGodRayOcclusion(vec2 uv) { return textureLod(occlusion, uv, 0.0f).r; }

void main() {
  const uvec2 texel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(texel, uvec2(p.blur.zw)))) return;
  const vec2 uv = (vec2(texel) + 0.5f) / p.blur.zw;
  imageStore(mask, ivec2(texel), vec4(godRayMaskAt(uv, p)));
}
