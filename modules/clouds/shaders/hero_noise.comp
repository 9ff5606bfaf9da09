#version 460
// Generates level 0 of the hero clouds' detail noise (kHeroNoiseSize^3, RGBA8, tiling): the
// curly alligator and the alligator at two frequencies each (cloud_noise.h's heroNoiseTexel()).
// One invocation per texel; hero_noise_mip.comp then makes the rest of its chain. Push
// constants: seed, size.
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
  imageStore(target, ivec3(texel), heroNoiseTexel(uvw, constants.seed));
}
