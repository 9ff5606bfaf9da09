#version 460
// Cloud ray-march (compute), at the trace resolution. With temporal reconstruction only one
// pixel per k x k tile is marched each frame (CloudUniforms.tileSize and tilePhase), so the
// dispatch covers exactly those pixels. Each builds its view ray, stops at the conservative
// scene distance (depth_downsample.comp), marches the layer with the shared model
// (cloud_march.h) and writes radiance + transmittance and the cloud depths into the trace
// images; reconstruct.comp turns them into a full picture.
// Inputs: binding 0 CloudUniforms; 1-4 shape noise, detail noise, weather map, curl noise
// (RGBA8, imageLoad); 5 scene distance (R32F, trace res); 7-8 weather maxima (empty-space
// skipping); with this frame's shadow map (kSpecShadowMapRead), 10-11 the map and its
// parameters (its terrain channel, its clouds' beyond the light cone;
// fxcontracts/cloud_shadow.h). Outputs: 6 the marched samples (radiance, transmittance, front
// and weighted depth in metres; packed, cloud_temporal.h); 9 work
// counters; with hero clouds (kSpecHeroClouds), 14-15 their atlas and instances (cloud_hero.h),
// 16 their light volume (cloud_hero_light.h) and 17 their detail noise.
// Feature toggles are specialization constants.
// Edge rays (kSpecEdgeRays, while the frame's kFlagEdgeRays is set): the tiles on a silhouette
// of last frame's reconstruction (12, trace history) are listed (13) by the tiles' march, and a
// second dispatch of this shader marches u.edgeRaysPerTile more rays for each, through other
// output pixels of its trace pixel, into its tile's edge-ray slots (edgeRaySlot());
// upsample.comp adds them to those output pixels' own samples. (More rays in the tiles' own
// invocations would cost, on lavapipe, as much as marching every tile again: a branch costs
// its lanes' whole group of 8 wherever one lane takes it. Gathered in each workgroup behind a
// barrier, the barrier alone cost the march 7 to 11%.)
// The near field (kSpecNearField; Settings::nearFieldMetres, Nubis³'s near/far split): a third
// dispatch marches every pixel of the near field's image (CloudUniforms.nearFieldExtent, half
// the trace's resolution) up to CloudUniforms.nearFieldMetres (18), while the tiles march from
// there on; near_field_resolve.comp and upsample.comp lay the one over the other.
// The sky light (kSpecSkyLight; Settings::skyLight): a fourth dispatch marches the rays of the
// sky-light map's upper half due this frame into 19, for sky_light.comp.
// References: Schneider & Vos 2017 (Nubis); Schneider 2022 (Nubis Evolved); Hillaire 2016.
#extension GL_GOOGLE_include_directive : require
#include "vkfx/spread_workgroups.h"

#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;

layout(constant_id = kSpecJitter) const uint kJitterMode = 1u;
layout(constant_id = kSpecDetail) const uint kDetailEnabled = 1u;
layout(constant_id = kSpecCheapSampling) const uint kCheapSampling = 1u;
layout(constant_id = kSpecMultipleScattering) const uint kMultipleScattering = 1u;
layout(constant_id = kSpecLightSteps) const uint kLightSteps = 6u;
layout(constant_id = kSpecCounters) const uint kCounters = 0u;
layout(constant_id = kSpecEmptySpace) const uint kEmptySpace = 1u;
layout(constant_id = kSpecShadowMapRead) const uint kShadowMapRead = 0u;
layout(constant_id = kSpecLightReuse) const uint kLightReuse = 1u;
layout(constant_id = kSpecEdgeRays) const uint kEdgeRays = 0u;
layout(constant_id = kSpecHeroClouds) const uint kHeroClouds = 0u;
layout(constant_id = kSpecHeroLight) const uint kHeroLight = kHeroLightVolume;
layout(constant_id = kSpecNearField) const uint kNearField = 0u;
layout(constant_id = kSpecWeatherRegions) const uint kWeatherRegions = 0u;
uint weatherRegionCapacity() { return kWeatherRegions; }
layout(constant_id = kSpecVortex) const uint kVortex = 0u;
bool vortexCompiledIn() { return kVortex != 0u; }
layout(constant_id = kSpecSkyLight) const uint kSkyLight = 0u;

#include "frame_uniforms.glsl"
layout(binding = kMarchShapeNoise, rgba8) uniform readonly image3D shapeNoise;
layout(binding = kMarchDetailNoise, rgba8) uniform readonly image3D detailNoise;
layout(binding = kMarchWeatherMap, rgba8) uniform readonly image2D weatherMap;
layout(binding = kMarchCurlNoise, rgba8) uniform readonly image2D curlNoise;
layout(binding = kMarchSceneDistance, r32f) uniform readonly image2D sceneDistance;
layout(binding = kMarchSamplesOut, rgba32ui) uniform writeonly uimage2D outSamples;
layout(binding = kMarchNearFieldOut, rgba32ui) uniform writeonly uimage2D nearFieldOut;
layout(binding = kMarchSkyLightOut, rgba16f) uniform writeonly image2D skyLightOut;
layout(binding = kMarchWeatherMaxFine, rgba8) uniform readonly image2D weatherMaxFine;
layout(binding = kMarchWeatherMaxCoarse, rgba8) uniform readonly image2D weatherMaxCoarse;
layout(binding = kMarchCounters, std430) buffer Counters { uint counters[]; };
layout(binding = kMarchTraceHistory, rgba32ui) uniform readonly uimage2D traceHistory;
// The tiles that march an edge ray this frame, and the dispatch that marches them.
layout(binding = kMarchEdgeRayList, std430) buffer EdgeRayList {
  uvec4 edgeRayDispatch;  // groups x, y, z (for vkCmdDispatchIndirect), and the tiles listed
  uint edgeRayTiles[];    // their fresh pixels, x | y << 16
};

vec4 fetchShapeNoise(ivec3 texel) { return imageLoad(shapeNoise, texel); }
vec4 fetchDetailNoise(ivec3 texel) { return imageLoad(detailNoise, texel); }
vec4 fetchWeather(ivec2 texel) { return imageLoad(weatherMap, texel); }
vec4 fetchCurl(ivec2 texel) { return imageLoad(curlNoise, texel); }
vec4 fetchWeatherMaxFine(ivec2 texel) { return imageLoad(weatherMaxFine, texel); }
vec4 fetchWeatherMaxCoarse(ivec2 texel) { return imageLoad(weatherMaxCoarse, texel); }

#define CLOUD_SHADOW_MAP_BINDING kMarchCloudShadow
#include "fxcontracts/cloud_shadow_sampled.glsl"
// Indexed like frame_uniforms.glsl's block, for the same reason.
layout(binding = kMarchCloudShadowParameters, std140) uniform ShadowMap {
  MarchShadowMap shadowMap[1];
};

// The share of the sun that a sample at a camera-relative (x, z) and an altitude gets past the
// terrain: read from the shadow map's terrain channel when the host gave its terrain.
float terrainSunLight(vec3 flatOffset, float altitude) {
  if ((kShadowMapRead & kShadowMapReadsTerrain) == 0u) return 1.0f;
  const uint slot = CLOUDS_FRAME_UNIFORMS_INDEX;
  float light = 1.0f;
  // Only below the highest terrain (a loop of 0 or 1 trips: most cloud is above it).
  for (int i = 0; i < (altitude < shadowMap[slot].terrainTopMetres ? 1 : 0); ++i) {
    const vec3 relative = vec3(flatOffset.x, altitude - u.cameraAltitudeMetres, flatOffset.z);
    vec4 uv01;
    vec4 uv23;
    CLOUD_SHADOW_COORDINATES(shadowMap[slot].map, relative, uv01, uv23);
    light = cloudShadowAt(shadowMap[slot].map.info, uv01, uv23, altitude, kCloudShadowTerrain).y;
  }
  return light;
}

// The optical depth of the clouds between the end of a sample's light cone and the sun: the
// shadow map's cloud channel where the cone ends, lightConeMetres towards the sun (Schneider
// 2022: long-distance shadows inside the clouds' own direct light). The map holds the whole
// sun ray through that point and the altitudes of its highest and lowest cloud; what it counts
// above the cone's end is the cloud beyond it, which the cone did not sample.
float farCloudOpticalDepth(vec3 flatOffset, float altitude) {
  if ((kShadowMapRead & kShadowMapReadsClouds) == 0u) return 0.0f;
  const uint slot = CLOUDS_FRAME_UNIFORMS_INDEX;
  const vec3 coneEnd = vec3(flatOffset.x, altitude - u.cameraAltitudeMetres, flatOffset.z) +
                       u.sunDirection * u.lightConeMetres;
  vec4 uv01;
  vec4 uv23;
  CLOUD_SHADOW_COORDINATES(shadowMap[slot].map, coneEnd, uv01, uv23);
  const float transmittance = cloudShadowAt(shadowMap[slot].map.info, uv01, uv23,
                                            coneEnd.y + u.cameraAltitudeMetres, kCloudShadowClouds)
                                  .x;
  return -log(max(transmittance, 1e-30f));
}

// Hero clouds: the atlas and this frame's instances (read only by the kSpecHeroClouds variant;
// the block is indexed like frame_uniforms.glsl's, for the same reason).
layout(binding = kMarchHeroAtlas, rgba8) uniform readonly image3D heroAtlas;
layout(binding = kMarchHeroClouds, std140) uniform HeroClouds { HeroCloudUniforms heroClouds[1]; };

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
uint heroLightMode() { return kHeroClouds != 0u ? kHeroLight : kHeroLightCone; }
// Their light volume (read only by the kHeroLightVolume variants with hero clouds).
layout(binding = kMarchHeroLight, r16f) uniform readonly image3D heroLight;
float fetchHeroLight(ivec3 texel) { return imageLoad(heroLight, texel).r; }
// Their detail noise (read only by the kSpecHeroClouds variant).
layout(binding = kMarchHeroNoise, rgba8) uniform readonly image3D heroNoise;
vec4 fetchHeroNoise(ivec3 texel) { return imageLoad(heroNoise, texel); }
// Its mean, read once by main() (the loops that ask for it fetch nothing).
vec4 gHeroNoiseMean = vec4(0.0f);
vec4 heroNoiseMean() { return gHeroNoiseMean; }

#include "cloud_march.h"
#include "cloud_temporal.h"

// How much of its transmittance range last frame's reconstruction spans around a tile's
// pixel (its 3 x 3 trace pixels) for the tile to march edge rays: the rims of clouds, where an
// output pixel's few own samples get its coverage wrong, and not the inside of a cloud or of a
// clear patch, where the spatial estimate is as good. (High above the layer, 640x360: at 0.25,
// one edge ray per tile gave 37.5 dB for 12% more time; at 0.5, two gave 39.3 dB for 13%.)
const float kEdgeContrast = 0.5f;

bool onSilhouette(uvec2 pixel) {
  float lo = 1.0f;
  float hi = 0.0f;
  for (int t = 0; t < 9; ++t) {
    const ivec2 q = clamp(ivec2(pixel) + ivec2(t % 3 - 1, t / 3 - 1), ivec2(0),
                          ivec2(u.traceExtent) - 1);
    const float transmittance = unpackCloudRadiance(imageLoad(traceHistory, q)).a;
    lo = min(lo, transmittance);
    hi = max(hi, transmittance);
  }
  return hi - lo > kEdgeContrast;
}

MarchOptions marchOptions() {
  MarchOptions options;
  options.detail = kDetailEnabled;
  options.cheapSampling = kCheapSampling;
  options.multipleScattering = kMultipleScattering;
  options.lightSteps = kLightSteps;
  options.emptySpace = kEmptySpace;
  options.lightReuse = kLightReuse;
  options.nearField = kNearField;
  return options;
}

void countWork(MarchResult result, uint ray) {
  if (kCounters == 0u) return;
  atomicAdd(counters[kCounterViewSamples], uint(result.viewSamples));
  atomicAdd(counters[kCounterLightSamples], uint(result.lightSamples));
  atomicAdd(counters[ray], 1u);
  atomicAdd(counters[kCounterEarlyExits], result.earlyExit);
  atomicAdd(counters[kCounterSkippedCells], uint(result.skippedCells));
}

// Marches the ray through `centre` (trace pixels) of `pixel`, whose steps start at
// `startOffset` (rayJitter()), and stores its sample at `slot`.
void marchRay(uvec2 pixel, vec2 centre, float startOffset, uvec2 slot) {
  const vec3 direction = pixelRayDirection(centre, vec2(u.traceExtent), u);
  const float distance = imageLoad(sceneDistance, ivec2(pixel)).r;
  const float jitter = rayJitter(pixel, startOffset, u.tileSize,
                                 (u.flags & kFlagRebuiltInsideCloud) != 0u, kJitterMode);
  const MarchResult result = marchClouds(
      direction, distance, jitter, lightJitter(u.lightRound, kJitterMode), u, marchOptions());
  imageStore(outSamples, ivec2(slot),
             packCloudSample(vec4(result.radiance, result.transmittance),
                             vec2(result.frontDepth, result.weightedDepth)));
  countWork(result, kCounterTracedPixels);
}

// The near field's pass: every near-field pixel's ray through its centre, up to the split
// (and the scene). Every pixel is marched every frame and resolved with its own neighbourhood
// (near_field_resolve.comp), so where its steps start must not repeat across the screen:
// interleaved gradient noise (Jimenez 2014) gives neighbours different starts without the short
// period a Bayer pattern would show, and the golden ratio moves them from frame to frame.
void marchNearField() {
  const uvec2 pixel = spreadInvocation(uvec2(kWorkgroupSize2D));
  if (any(greaterThanEqual(pixel, u.nearFieldExtent))) return;
  const vec3 direction = pixelRayDirection(vec2(pixel) + 0.5f, vec2(u.nearFieldExtent), u);
  // The nearest geometry of the 2 x 2 trace pixels it covers (the upsample hides what lies
  // behind each output pixel's own).
  float distance = kInfiniteDistance;
  for (int t = 0; t < 4; ++t) {
    const ivec2 trace = min(ivec2(pixel * 2u) + ivec2(t & 1, t >> 1), ivec2(u.traceExtent) - 1);
    distance = min(distance, imageLoad(sceneDistance, trace).r);
  }
  const float gradientNoise =
      fract(52.9829189f * fract(dot(vec2(pixel), vec2(0.06711056f, 0.00583715f))));
  const float jitter =
      kJitterMode == 0u ? 0.5f
                        : fract(gradientNoise + 0.6180340f * float(u.temporalIndex & 0xffffu));
  const MarchResult result = marchClouds(
      direction, distance, jitter, lightJitter(u.lightRound, kJitterMode), u, marchOptions());
  imageStore(nearFieldOut, ivec2(pixel),
             packCloudSample(vec4(result.radiance, result.transmittance),
                             vec2(result.frontDepth, result.weightedDepth)));
  countWork(result, kCounterNearFieldRays);
}

// The sky light's pass: the rays of the sky-light map's upper half due this frame
// (u.skyLightRefresh), one per invocation, from under the camera (skyLightAltitude()) through
// the whole layer (no scene stops them), with the frame's lighting. sky_light.comp lays them
// over the host's sky. Each refresh of a texel starts its steps elsewhere (the golden ratio),
// so the map's texels, seen together, average the steps' noise.
void marchSkyLight() {
  const uvec2 id = spreadInvocation(uvec2(kWorkgroupSize2D));
  const bool everyTexel = u.skyLightRefresh == kSkyLightEveryTexel;
  const uvec2 texel =
      everyTexel ? id : id * 2u + uvec2(u.skyLightRefresh & 1u, u.skyLightRefresh >> 1u);
  if (any(greaterThanEqual(texel, uvec2(kSkyLightWidth, kSkyLightHeight / 2u)))) return;
  const vec3 direction = skyLightDirection(texel);
  const float jitter = skyLightJitter(texel, u.temporalIndex, kJitterMode);
  MarchOptions options = marchOptions();
  options.nearField = kMarchWholeRay;
  u.cameraAltitudeMetres = skyLightAltitude(u);  // the frame's own copy (frame_uniforms.glsl)
  const MarchResult result = marchClouds(direction, kInfiniteDistance, jitter,
                                         lightJitter(u.lightRound, kJitterMode), u, options);
  imageStore(skyLightOut, ivec2(texel), vec4(result.radiance, result.transmittance));
}

// Invocations in a workgroup: the second dispatch's groups are counted in these.
const uint kGroupInvocations = kWorkgroupSize2D * kWorkgroupSize2D;

// The second dispatch: one edge ray per invocation, a listed tile's rays side by side.
void marchListedEdgeRay() {
  const uint index = gl_WorkGroupID.x * kGroupInvocations + gl_LocalInvocationIndex;
  const uint perTile = u.edgeRaysPerTile;
  if (index >= edgeRayDispatch.w * perTile) return;
  const uint packed = edgeRayTiles[index / perTile];
  const uvec2 pixel = uvec2(packed & 0xffffu, packed >> 16u);
  const uint ray = index % perTile;
  marchRay(pixel, vec2(pixel) + 0.5f + edgeSubpixelOffset(ray, u),
           ray == 0u ? u.edgeRayStartOffsets.x : u.edgeRayStartOffsets.y,
           edgeRaySlot(pixel, ray, u));
  if (kCounters != 0u) atomicAdd(counters[kCounterEdgeRays], 1u);
}

void main() {
  loadFrameUniforms();
  if (heroCloudCount() > 0u)
    gHeroNoiseMean = fetchHeroNoise(heroNoiseTexelAddress(kHeroNoiseLevels - 1, ivec3(0)));
  if (kNearField != 0u) {
    marchNearField();
    return;
  }
  if (kSkyLight != 0u) {
    marchSkyLight();
    return;
  }
  if (kEdgeRays == kEdgeRaysMarch) {
    marchListedEdgeRay();
    return;
  }
  const uvec2 tile = spreadInvocation(uvec2(kWorkgroupSize2D));
  const uvec2 pixel = tile * u.tileSize + u.tilePhase;
  const uvec2 extent = u.traceExtent;
  if (any(greaterThanEqual(pixel, extent))) return;

  const vec2 offset = kJitterMode == 2u ? u.subpixelOffset : vec2(0.0f);
  marchRay(pixel, vec2(pixel) + 0.5f + offset, u.rayStartOffset, pixel);

  // With edge rays, every tile's slots say whether they hold one this frame. (The first slot
  // lies beyond the image where the second does: a tile without room for both marches none.)
  CLOUDS_WHEN(kEdgeRays == kEdgeRaysFind && (u.flags & kFlagEdgeRays) != 0u &&
              all(lessThan(edgeRaySlot(pixel, 0u, u), extent))) {
    if (onSilhouette(pixel)) {
      const uint listed = atomicAdd(edgeRayDispatch.w, 1u);
      edgeRayTiles[listed] = pixel.x | pixel.y << 16u;
      const uint lastRay = (listed + 1u) * u.edgeRaysPerTile - 1u;
      atomicMax(edgeRayDispatch.x, lastRay / kGroupInvocations + 1u);
    } else {
      for (uint ray = 0u; ray < u.edgeRaysPerTile; ++ray) {
        imageStore(outSamples, ivec2(edgeRaySlot(pixel, ray, u)), uvec4(kNoEdgeRay));
      }
    }
  }
}
