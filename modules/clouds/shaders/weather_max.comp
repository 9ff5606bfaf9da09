#version 460
// One level of the empty-space-skipping grid: each output cell holds the maximum coverage (R)
// and cloud type (G) of the `cell` x `cell` source texels it covers plus a one-texel apron
// (the march filters bilinearly, so a neighbouring texel can leak into the cell). Wraps.
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba8) uniform readonly image2D source;
layout(binding = 1, rgba8) uniform writeonly image2D target;
layout(push_constant) uniform Constants { uvec4 params; };  // x source size, y cell, z target size

void main() {
  const uvec2 cell = gl_GlobalInvocationID.xy;
  const int targetSize = int(params.z);
  if (any(greaterThanEqual(ivec2(cell), ivec2(targetSize)))) return;
  const int size = int(params.x);
  const int step = int(params.y);
  vec2 maxima = vec2(0.0f);
  for (int y = -1; y <= step; ++y) {
    for (int x = -1; x <= step; ++x) {
      const ivec2 texel = (ivec2(cell) * step + ivec2(x, y) + size) % size;
      maxima = max(maxima, imageLoad(source, texel).xy);
    }
  }
  imageStore(target, ivec2(cell), vec4(maxima, 0.0f, 1.0f));
}
