#version 460
// The hero clouds' light volume (compute): sweeps the instances the push constants name into
// their slots, one workgroup per instance, slice by slice from the sun's side
// (cloud_hero_light.h's heroLightSweepTexel()); each slice reads the one before it, which the
// workgroup's barrier makes visible. The host asks for a sweep only when an instance's asset,
// sun, or life moved on from what its slot holds (hero_light_volume.h), so most frames record
// none.
// Inputs: 0 the hero atlas (RGBA8 3D), 1 this frame's instances (HeroCloudUniforms, their
// slots in count.y and z), 3 the detail noise (its mean). Output: 2 the light volume (R16F 3D,
// slots in a 2 x 2 x 2 grid).
#extension GL_GOOGLE_include_directive : require

#include "cloud_types.h"

const uint kLanes = 128u;
layout(local_size_x = kLanes) in;

layout(binding = kLightSweepAtlas, rgba8) uniform readonly image3D heroAtlas;
// Indexed by a push constant (always 0), as frame_uniforms.glsl explains: the instances decide
// loop bounds, which lavapipe would otherwise inline and recompile for at every bind.
layout(binding = kLightSweepClouds, std140) uniform HeroClouds {
  HeroCloudUniforms heroClouds[1];
};
layout(binding = kLightSweepVolume, r16f) uniform coherent image3D lightVolume;
layout(push_constant) uniform Constants { HeroLightConstants c; };

uint heroCloudCount() { return heroClouds[c.blockIndex].count.x; }
uvec4 heroCloudHeader() { return heroClouds[c.blockIndex].count; }
HeroCloudInstance heroCloud(uint index) { return heroClouds[c.blockIndex].instance[index]; }
bool heroLifeCompiledIn() { return true; }  // one variant: the sweep is rare
vec4 fetchHeroAtlas(ivec3 texel) { return imageLoad(heroAtlas, texel); }
layout(binding = kLightSweepNoise, rgba8) uniform readonly image3D heroNoise;
vec4 fetchHeroNoise(ivec3 texel) { return imageLoad(heroNoise, texel); }
// Its mean, read once by main() (the loops that ask for it fetch nothing).
vec4 gHeroNoiseMean = vec4(0.0f);
vec4 heroNoiseMean() { return gHeroNoiseMean; }
float fetchHeroLight(ivec3 texel) { return imageLoad(lightVolume, texel).r; }

#include "cloud_hero_light.h"

// The instance of this workgroup: the gl_WorkGroupID.x-th set bit of c.instances.
uint sweptInstance() {
  uint seen = 0u;
  uint instance = 0u;
  for (uint i = 0u; i < kMaxHeroClouds; ++i) {
    if (((c.instances >> i) & 1u) == 0u) continue;
    if (seen == gl_WorkGroupID.x) instance = i;
    ++seen;
  }
  return instance;
}

void main() {
  gHeroNoiseMean = fetchHeroNoise(heroNoiseTexelAddress(kHeroNoiseLevels - 1, ivec3(0)));
  const uint index = sweptInstance();
  const HeroCloudInstance h = heroCloud(index);
  const ivec3 size = heroLightSize(h);
  const ivec3 slotOrigin = heroLightSlotOrigin(index);
  const vec3 sun = heroSunIndexDirection(h, c.sunDirection.xyz);
  const int axis = heroLightAxis(sun);
  const int slices = size[axis];
  const int perSlice = size[(axis + 1) % 3] * size[(axis + 2) % 3];
  for (int s = 0; s < slices; ++s) {
    for (int t = int(gl_LocalInvocationIndex); t < perSlice; t += int(kLanes)) {
      const ivec3 j = heroLightSweepTexelAt(size, sun, axis, s, t);
      const float opticalDepth = heroLightSweepTexel(h, j, sun, axis, size, slotOrigin);
      imageStore(lightVolume, j + slotOrigin, vec4(opticalDepth));
    }
    memoryBarrierImage();
    barrier();
  }
}
