#version 460
// Cloud shadow map (compute): one cascade of the Beer shadow map per dispatch, one invocation
// per texel. Each texel's sun ray is marched up through the layer with the shared model
// (cloud_shadow_march.h) and stored as the receivers read it (fxcontracts/cloud_shadow.h): optical
// depth, highest and lowest cloud altitude; the terrain channel kept or emptied
// (terrain_shadow_map.comp writes it).
// Inputs: binding 0 CloudUniforms (this frame's field: camera-relative offsets, coverage,
// extinction); 1 shape noise; 2 weather map; 3-4 weather maxima (empty-space skipping); with
// hero clouds, 7-8 their atlas and instances (cloud_hero.h) and 9 their detail noise; push
// constants ShadowMapConstants (the cascade's placement and the rows made). Output: 5 the
// cascade atlas (its square for this cascade) or, for a cascade made over several frames, 6 the
// spare cascade (copied into the atlas after its last rows are made).
// References: Schneider & Vos 2017 (Nubis); Hillaire 2016 (Beer shadow maps, Frostbite).
#extension GL_GOOGLE_include_directive : require

#include "cloud_types.h"
#include "fxcontracts/cloud_shadow.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;

layout(constant_id = kSpecShadowEmptySpace) const uint kEmptySpace = 1u;
layout(constant_id = kSpecShadowHeroClouds) const uint kHeroClouds = 0u;
layout(constant_id = kSpecShadowWeatherRegions) const uint kWeatherRegions = 0u;
uint weatherRegionCapacity() { return kWeatherRegions; }
layout(constant_id = kSpecShadowVortex) const uint kVortex = 0u;
bool vortexCompiledIn() { return kVortex != 0u; }

// Its push constants (ShadowMapConstants, inside TerrainShadowConstants' 128 bytes) have no
// spare word for frame_uniforms.glsl's index, so this pass keeps the lane-by-lane loads. Making
// one (the rows packed into one word) bought nothing: the pass took as long (Medium 1.14-1.28 ms
// either way, clouds_bench's shadow section, two rounds interleaved), its time being its
// marches, not its one load of the uniforms.
#define CLOUDS_FRAME_UNIFORMS_INDEX (gl_NumWorkGroups.z - 1u)
#include "frame_uniforms.glsl"
layout(binding = kShadowShapeNoise, rgba8) uniform readonly image3D shapeNoise;
layout(binding = kShadowWeatherMap, rgba8) uniform readonly image2D weatherMap;
layout(binding = kShadowWeatherMaxFine, rgba8) uniform readonly image2D weatherMaxFine;
layout(binding = kShadowWeatherMaxCoarse, rgba8) uniform readonly image2D weatherMaxCoarse;
layout(binding = kShadowMapOut, rgba16f) uniform image2D shadowMap;
layout(binding = kShadowMapSpare, rgba16f) uniform writeonly image2D spareCascade;
layout(push_constant) uniform Constants { ShadowMapConstants c; };

vec4 fetchShapeNoise(ivec3 texel) { return imageLoad(shapeNoise, texel); }
vec4 fetchWeather(ivec2 texel) { return imageLoad(weatherMap, texel); }
vec4 fetchWeatherMaxFine(ivec2 texel) { return imageLoad(weatherMaxFine, texel); }
vec4 fetchWeatherMaxCoarse(ivec2 texel) { return imageLoad(weatherMaxCoarse, texel); }
// The shadow rays take no detail: these are never reached.
vec4 fetchDetailNoise(ivec3 texel) { return vec4(0.0f); }
vec4 fetchCurl(ivec2 texel) { return vec4(0.5f); }
float terrainSunLight(vec3 flatOffset, float altitude) { return 1.0f; }
float farCloudOpticalDepth(vec3 flatOffset, float altitude) { return 0.0f; }
// Hero clouds (read only by the kSpecShadowHeroClouds variant), indexed as the uniforms are.
layout(binding = kShadowHeroAtlas, rgba8) uniform readonly image3D heroAtlas;
layout(binding = kShadowHeroClouds, std140) uniform HeroClouds { HeroCloudUniforms heroClouds[1]; };
uint heroCloudCount() {
  return kHeroClouds != 0u ? heroClouds[CLOUDS_FRAME_UNIFORMS_INDEX].count.x : 0u;
}
bool heroLifeCompiledIn() {
  return kHeroClouds == kHeroCloudsLiving;
}
HeroCloudInstance heroCloud(uint index) {
  return heroClouds[CLOUDS_FRAME_UNIFORMS_INDEX].instance[index];
}
vec4 fetchHeroAtlas(ivec3 texel) { return imageLoad(heroAtlas, texel); }
uvec4 heroCloudHeader() { return heroClouds[CLOUDS_FRAME_UNIFORMS_INDEX].count; }
layout(binding = kShadowHeroNoise, rgba8) uniform readonly image3D heroNoise;
vec4 fetchHeroNoise(ivec3 texel) { return imageLoad(heroNoise, texel); }
// Its mean, read once by main() (the loops that ask for it fetch nothing).
vec4 gHeroNoiseMean = vec4(0.0f);
vec4 heroNoiseMean() { return gHeroNoiseMean; }

#include "cloud_shadow_march.h"

void main() {
  loadFrameUniforms();
  if (heroCloudCount() > 0u)
    gHeroNoiseMean = fetchHeroNoise(heroNoiseTexelAddress(kHeroNoiseLevels - 1, ivec3(0)));
  const uvec2 texel = uvec2(gl_GlobalInvocationID.x, c.firstRow + gl_GlobalInvocationID.y);
  if (texel.x >= c.resolution || gl_GlobalInvocationID.y >= c.rowCount) return;
  const ShadowColumn column = marchShadowTexel(c, texel, kEmptySpace, u);
  const ivec2 atlas = ivec2(c.cascade * c.resolution + texel.x, texel.y);
  // The terrain does not move: a cascade remade over the same rays keeps its terrain channel.
  float terrain = kCloudShadowNoTerrain;
  const int keep = (c.flags & kShadowTexelKeepTerrain) != 0u ? 1 : 0;
  for (int i = 0; i < keep; ++i) terrain = imageLoad(shadowMap, atlas).a;
  const vec4 value = vec4(min(column.opticalDepth, kCloudShadowMaxDepth), column.frontAltitude,
                          column.backAltitude, terrain);
  if ((c.flags & kShadowTexelToSpare) != 0u) {
    imageStore(spareCascade, ivec2(texel), value);
  } else {
    imageStore(shadowMap, atlas, value);
  }
}
