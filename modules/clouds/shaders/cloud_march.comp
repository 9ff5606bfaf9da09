#version 460
// Cloud ray-march (compute), at the trace resolution. With temporal reconstruction only one
// pixel per k x k tile is marched each frame (CloudUniforms.tileSize and tilePhase), so the
// dispatch covers exactly those pixels. Each builds its view ray, stops at the conservative
// scene distance (depth_downsample.comp), marches the layer with the shared model
// (cloud_march.h) and writes radiance + transmittance and the cloud depths into the trace
// images; reconstruct.comp turns them into a full picture.
// Inputs: binding 0 CloudUniforms; 1-4 shape noise, detail noise, weather map, curl noise
// (RGBA8, imageLoad); 5 scene distance (R32F, trace res); 7-8 weather maxima (empty-space
// skipping); with the terrain's shadow, 10-11 the cloud shadow map and its parameters (its
// terrain channel, vkfx/cloud_shadow.h). Outputs: 6 the marched samples (radiance,
// transmittance, front and weighted depth in metres; packed, cloud_temporal.h); 9 work
// counters. Feature toggles are specialization constants.
// References: Schneider & Vos 2017 (Nubis); Schneider 2022 (Nubis Evolved); Hillaire 2016.
#extension GL_GOOGLE_include_directive : require

#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;

layout(constant_id = kSpecJitter) const uint kJitterMode = 1u;
layout(constant_id = kSpecDetail) const uint kDetailEnabled = 1u;
layout(constant_id = kSpecCheapSampling) const uint kCheapSampling = 1u;
layout(constant_id = kSpecMultipleScattering) const uint kMultipleScattering = 1u;
layout(constant_id = kSpecLightSteps) const uint kLightSteps = 6u;
layout(constant_id = kSpecCounters) const uint kCounters = 0u;
layout(constant_id = kSpecEmptySpace) const uint kEmptySpace = 1u;
layout(constant_id = kSpecTerrainShadow) const uint kTerrainShadow = 0u;
layout(constant_id = kSpecLightReuse) const uint kLightReuse = 1u;

#include "frame_uniforms.glsl"
layout(binding = kMarchShapeNoise, rgba8) uniform readonly image3D shapeNoise;
layout(binding = kMarchDetailNoise, rgba8) uniform readonly image3D detailNoise;
layout(binding = kMarchWeatherMap, rgba8) uniform readonly image2D weatherMap;
layout(binding = kMarchCurlNoise, rgba8) uniform readonly image2D curlNoise;
layout(binding = kMarchSceneDistance, r32f) uniform readonly image2D sceneDistance;
layout(binding = kMarchSamplesOut, rgba32ui) uniform writeonly uimage2D outSamples;
layout(binding = kMarchWeatherMaxFine, rgba8) uniform readonly image2D weatherMaxFine;
layout(binding = kMarchWeatherMaxCoarse, rgba8) uniform readonly image2D weatherMaxCoarse;
layout(binding = kMarchCounters, std430) buffer Counters { uint counters[]; };

vec4 fetchShapeNoise(ivec3 texel) { return imageLoad(shapeNoise, texel); }
vec4 fetchDetailNoise(ivec3 texel) { return imageLoad(detailNoise, texel); }
vec4 fetchWeather(ivec2 texel) { return imageLoad(weatherMap, texel); }
vec4 fetchCurl(ivec2 texel) { return imageLoad(curlNoise, texel); }
vec4 fetchWeatherMaxFine(ivec2 texel) { return imageLoad(weatherMaxFine, texel); }
vec4 fetchWeatherMaxCoarse(ivec2 texel) { return imageLoad(weatherMaxCoarse, texel); }

#define CLOUD_SHADOW_MAP_BINDING kMarchCloudShadow
#include "vkfx/cloud_shadow_sampled.glsl"
// Indexed like frame_uniforms.glsl's block, for the same reason.
layout(binding = kMarchCloudShadowParameters, std140) uniform TerrainShadow {
  MarchTerrainShadow terrainShadow[1];
};

// The share of the sun that a sample at a camera-relative (x, z) and an altitude gets past the
// terrain: read from the shadow map's terrain channel when the host gave its terrain.
float terrainSunLight(vec3 flatOffset, float altitude) {
  if (kTerrainShadow == 0u) return 1.0f;
  const uint slot = CLOUDS_FRAME_UNIFORMS_INDEX;
  float light = 1.0f;
  // Only below the highest terrain (a loop of 0 or 1 trips: most cloud is above it).
  for (int i = 0; i < (altitude < terrainShadow[slot].terrainTopMetres ? 1 : 0); ++i) {
    const vec3 relative = vec3(flatOffset.x, altitude - u.cameraAltitudeMetres, flatOffset.z);
    vec4 uv01;
    vec4 uv23;
    CLOUD_SHADOW_COORDINATES(terrainShadow[slot].map, relative, uv01, uv23);
    light = cloudShadowAt(terrainShadow[slot].map.info, uv01, uv23, altitude, kCloudShadowTerrain)
                .y;
  }
  return light;
}

#include "cloud_march.h"
#include "cloud_temporal.h"

void main() {
  loadFrameUniforms();
  const uvec2 tile = gl_GlobalInvocationID.xy;
  const uvec2 pixel = tile * u.tileSize + u.tilePhase;
  const uvec2 extent = u.traceExtent;
  if (any(greaterThanEqual(pixel, extent))) return;

  const vec2 centre = vec2(pixel) + 0.5f + (kJitterMode == 2u ? u.subpixelOffset : vec2(0.0f));
  const vec3 direction = pixelRayDirection(centre, vec2(extent), u);
  const float distance = imageLoad(sceneDistance, ivec2(pixel)).r;

  MarchOptions options;
  options.detail = kDetailEnabled;
  options.cheapSampling = kCheapSampling;
  options.multipleScattering = kMultipleScattering;
  options.lightSteps = kLightSteps;
  options.emptySpace = kEmptySpace;
  options.lightReuse = kLightReuse;
  const float jitter = rayJitter(pixel, u.rayStartOffset, u.tileSize,
                                 (u.flags & kFlagRebuiltInsideLayer) != 0u, kJitterMode);
  const MarchResult result = marchClouds(
      direction, distance, jitter, lightJitter(u.lightRound, kJitterMode), u, options);

  imageStore(outSamples, ivec2(pixel),
             packCloudSample(vec4(result.radiance, result.transmittance),
                             vec2(result.frontDepth, result.weightedDepth)));
  if (kCounters != 0u) {
    atomicAdd(counters[kCounterViewSamples], uint(result.viewSamples));
    atomicAdd(counters[kCounterLightSamples], uint(result.lightSamples));
    atomicAdd(counters[kCounterTracedPixels], 1u);
    atomicAdd(counters[kCounterEarlyExits], result.earlyExit);
    atomicAdd(counters[kCounterSkippedCells], uint(result.skippedCells));
  }
}
