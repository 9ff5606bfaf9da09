#version 460
// Cloud ray-march (compute): one invocation per output pixel. Builds the pixel's view ray,
// reads the host depth to stop at geometry, marches the cloud layer with the shared model
// (cloud_march.h) and writes radiance + transmittance and the cloud depths.
// Inputs: binding 0 CloudUniforms (UBO); 1-4 shape noise, detail noise, weather map, curl
// noise (RGBA8 storage images, read with imageLoad); 5 host depth (texelFetch).
// Outputs: 6 RGBA16F radiance (rgb premultiplied) + transmittance (a); 7 RG32F front depth
// and transmittance-weighted depth (m). Feature toggles are specialization constants.
// References: Schneider & Vos 2017 (Nubis); Schneider 2022 (Nubis Evolved); Hillaire 2016.
#extension GL_GOOGLE_include_directive : require

#include "cloud_types.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(constant_id = 0) const uint kJitterMode = 1u;
layout(constant_id = 1) const uint kDetailEnabled = 1u;
layout(constant_id = 2) const uint kCheapSampling = 1u;
layout(constant_id = 3) const uint kMultipleScattering = 1u;
layout(constant_id = 4) const uint kLightSteps = 6u;

layout(binding = 0, std140) uniform Uniforms { CloudUniforms u; };
layout(binding = 1, rgba8) uniform readonly image3D shapeNoise;
layout(binding = 2, rgba8) uniform readonly image3D detailNoise;
layout(binding = 3, rgba8) uniform readonly image2D weatherMap;
layout(binding = 4, rgba8) uniform readonly image2D curlNoise;
layout(binding = 5) uniform sampler2D sceneDepth;
layout(binding = 6, rgba16f) uniform writeonly image2D outRadiance;
layout(binding = 7, rg32f) uniform writeonly image2D outDepth;

vec4 fetchShapeNoise(ivec3 texel) { return imageLoad(shapeNoise, texel); }
vec4 fetchDetailNoise(ivec3 texel) { return imageLoad(detailNoise, texel); }
vec4 fetchWeather(ivec2 texel) { return imageLoad(weatherMap, texel); }
vec4 fetchCurl(ivec2 texel) { return imageLoad(curlNoise, texel); }

#include "cloud_march.h"

void main() {
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  const uvec2 extent = u.extent.xy;
  if (any(greaterThanEqual(pixel, extent))) return;

  const vec2 centre = vec2(pixel) + 0.5f;
  const vec3 direction = pixelRayDirection(centre, vec2(extent), u);
  const float depth = texelFetch(sceneDepth, ivec2(pixel), 0).r;
  const float sceneDistance = sceneDistanceFromDepth(depth, centre, vec2(extent), u);

  MarchOptions options;
  options.detail = kDetailEnabled;
  options.cheapSampling = kCheapSampling;
  options.multipleScattering = kMultipleScattering;
  options.lightSteps = kLightSteps;
  const float jitter = rayJitter(pixel, u.frame.x, kJitterMode);
  const MarchResult result = marchClouds(direction, sceneDistance, jitter, u, options);

  imageStore(outRadiance, ivec2(pixel), vec4(result.radiance, result.transmittance));
  imageStore(outDepth, ivec2(pixel), vec4(result.frontDepth, result.weightedDepth, 0.0f, 0.0f));
}
