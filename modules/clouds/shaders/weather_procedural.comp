#version 460
// Generates the procedural weather map (512^2 RGBA8): R coverage, G type, B density
// (cloud_weather.h). Push constants: evolution phase, seed and the first row: the map may be
// generated a band of rows per dispatch (spread over frames).
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"
#include "cloud_weather.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(binding = kGeneratorTarget, rgba8) uniform writeonly image2D target;
layout(push_constant) uniform Constants { WeatherConstants constants; };

void main() {
  const uvec2 texel = gl_GlobalInvocationID.xy + uvec2(0u, constants.firstRow);
  if (any(greaterThanEqual(texel, uvec2(kWeatherMapSize)))) return;
  const vec2 uv = (vec2(texel) + 0.5f) / float(kWeatherMapSize);
  imageStore(target, ivec2(texel),
             proceduralWeatherTexel(uv, constants.evolutionPhase, constants.seed));
}
