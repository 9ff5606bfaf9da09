#version 460
// One level of the hero clouds' detail noise chain (laid out as cloud_hero.h's
// heroNoiseTexelAddress() says), from the level below: each texel the mean of the 2 x 2 x 2 it
// covers, every channel (a box filter; the noise tiles, so every level does too). Unlike the
// other noises' chains nothing is packed: cloud_hero.h blends the four channels per sample.
// Push constants: level-0 size, level.
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"
// The address function only: the prototypes the header declares are not called here.
#include "cloud_hero.h"

layout(local_size_x = kWorkgroupSize3D, local_size_y = kWorkgroupSize3D,
       local_size_z = kWorkgroupSize3D) in;
layout(binding = kGeneratorTarget, rgba8) uniform image3D chain;
layout(push_constant) uniform Constants { NoiseMipConstants constants; };

void main() {
  const int n = int(constants.size);
  const int level = int(constants.level);
  const int size = n >> level;
  const ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(texel, ivec3(size)))) return;
  vec4 sum = vec4(0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    const ivec3 below = 2 * texel + ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
    sum += imageLoad(chain, heroNoiseTexelAddress(level - 1, below));
  }
  imageStore(chain, heroNoiseTexelAddress(level, texel), sum * 0.125f);
}
