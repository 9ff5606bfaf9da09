#version 460
// Makes one level of a 3D noise's mip chain from the level above: each texel the mean of the
// 2 x 2 x 2 texels it covers (a box filter; the noise tiles, so every level does too). The chain
// lives in the noise's own image (noiseLevelOrigin()). Push constants: level-0 size, level.
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"
#include "cloud_sampling.h"

layout(local_size_x = kWorkgroupSize3D, local_size_y = kWorkgroupSize3D,
       local_size_z = kWorkgroupSize3D) in;
layout(binding = kGeneratorTarget, rgba8) uniform image3D chain;
layout(push_constant) uniform Constants { NoiseMipConstants constants; };

void main() {
  const int n = int(constants.size);
  const int level = int(constants.level);
  const ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(texel, ivec3(n >> level)))) return;
  const ivec3 source = noiseLevelOrigin(level - 1, n) + 2 * texel;
  vec4 sum = vec4(0.0f);
  for (int z = 0; z < 2; ++z) {
    for (int y = 0; y < 2; ++y) {
      for (int x = 0; x < 2; ++x) sum += imageLoad(chain, source + ivec3(x, y, z));
    }
  }
  imageStore(chain, noiseLevelOrigin(level, n) + texel, sum * 0.125f);
}
