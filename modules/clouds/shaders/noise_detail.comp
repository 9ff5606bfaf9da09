#version 460
// Generates level 0 of the high-frequency detail noise (32^3, tiling): Worley fBm at three
// frequencies (detailNoiseValue(), cloud_noise.h), in every channel until noise_mip.comp packs
// the level. One invocation per texel. Push constants: seed, size.
#extension GL_GOOGLE_include_directive : require
#include "cloud_noise.h"
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize3D, local_size_y = kWorkgroupSize3D,
       local_size_z = kWorkgroupSize3D) in;
layout(binding = kGeneratorTarget, rgba8) uniform writeonly image3D target;
layout(push_constant) uniform Constants { NoiseConstants constants; };

void main() {
  const uvec3 texel = gl_GlobalInvocationID;
  const uint size = constants.size;
  if (any(greaterThanEqual(texel, uvec3(size)))) return;
  const vec3 uvw = (vec3(texel) + 0.5f) / float(size);
  const float value = detailNoiseValue(highFrequencyNoiseTexel(uvw, constants.seed));
  imageStore(target, ivec3(texel), vec4(value));
}
