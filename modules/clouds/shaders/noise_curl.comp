#version 460
// Generates the 2D curl noise (128^2 RGBA8, tiling; RG = curl encoded as 0.5 + 0.5 c) that
// swirls the detail noise (cloud_noise.h). Push constants: seed, size.
#extension GL_GOOGLE_include_directive : require
#include "cloud_noise.h"
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(binding = kGeneratorTarget, rgba8) uniform writeonly image2D target;
layout(push_constant) uniform Constants { NoiseConstants constants; };

void main() {
  const uvec2 texel = gl_GlobalInvocationID.xy;
  const uint size = constants.size;
  if (any(greaterThanEqual(texel, uvec2(size)))) return;
  const vec2 uv = (vec2(texel) + 0.5f) / float(size);
  const vec2 curl = curlNoiseTexel(uv, 1.0f / float(size), constants.seed);
  imageStore(target, ivec2(texel), vec4(curl, 0.0f, 1.0f));
}
