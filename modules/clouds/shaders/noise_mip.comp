#version 460
// Packs a 3D noise's chain for its 2-fetch trilinear filtering (cloud_sampling.h: texel (x, y,
// z) of a level holds the level's values at (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1) of
// layer z), level by level:
//  - level 0 (made by the generator with its value in R): each texel takes its neighbours' R,
//    in four passes by the parity of x and y, so that no invocation reads a texel that another
//    of the same pass writes (a texel's own R does not change);
//  - every level above, from the packed level below: each of its four values the mean of the
//    2 x 2 x 2 values it covers (a box filter; the noise tiles, so every level does too), which
//    two fetches of the level below give.
// The chain lives in the noise's own image (noiseLevelOrigin()). Push constants: level-0 size,
// level, parity.
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"
#include "cloud_sampling.h"

layout(local_size_x = kWorkgroupSize3D, local_size_y = kWorkgroupSize3D,
       local_size_z = kWorkgroupSize3D) in;
layout(binding = kGeneratorTarget, rgba8) uniform image3D chain;
layout(push_constant) uniform Constants { NoiseMipConstants constants; };

// The value at `texel` (wrapped) of a level `size` texels wide whose origin is `origin`.
float valueAt(ivec3 origin, int size, ivec3 texel) {
  return imageLoad(chain, origin + (texel & (size - 1))).x;
}

// The mean of the 2 x 2 x 2 values of the packed level below (`origin`, `size` texels wide)
// that the value at `texel` of this level covers.
float meanBelow(ivec3 origin, int size, ivec3 texel) {
  const ivec3 below = origin + ((2 * texel) & (size - 1));
  const vec4 lower = imageLoad(chain, below);
  const int upperZ = origin.z + ((2 * texel.z + 1) & (size - 1));
  const vec4 upper = imageLoad(chain, ivec3(below.x, below.y, upperZ));
  return dot(lower + upper, vec4(0.125f));
}

void main() {
  const int n = int(constants.size);
  const int level = int(constants.level);
  const int size = n >> level;
  const ivec3 origin = noiseLevelOrigin(level, n);
  if (level == 0) {
    // This pass's texels: those of one parity of x and y (a dispatch of n/2 x n/2 x n).
    const ivec3 texel = ivec3(2 * ivec2(gl_GlobalInvocationID.xy) +
                                  ivec2(int(constants.parity & 1u), int(constants.parity >> 1u)),
                              int(gl_GlobalInvocationID.z));
    if (any(greaterThanEqual(texel, ivec3(size)))) return;
    imageStore(chain, texel,
               vec4(valueAt(origin, size, texel), valueAt(origin, size, texel + ivec3(1, 0, 0)),
                    valueAt(origin, size, texel + ivec3(0, 1, 0)),
                    valueAt(origin, size, texel + ivec3(1, 1, 0))));
    return;
  }
  const ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(texel, ivec3(size)))) return;
  const ivec3 belowOrigin = noiseLevelOrigin(level - 1, n);
  const int belowSize = size * 2;
  imageStore(chain, origin + texel,
             vec4(meanBelow(belowOrigin, belowSize, texel),
                  meanBelow(belowOrigin, belowSize, (texel + ivec3(1, 0, 0)) & (size - 1)),
                  meanBelow(belowOrigin, belowSize, (texel + ivec3(0, 1, 0)) & (size - 1)),
                  meanBelow(belowOrigin, belowSize, (texel + ivec3(1, 1, 0)) & (size - 1))));
}
