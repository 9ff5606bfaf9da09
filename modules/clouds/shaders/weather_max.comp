#version 460
// One level of the empty-space-skipping grid from the level below it (the weather map, or the
// fine maxima): the per-cell maxima of cloud_weather_maxima.h.
// Inputs: the source level (RGBA8), push constants MaximaConstants. Output: the target level.
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(binding = kMaximaSource, rgba8) uniform readonly image2D source;
layout(binding = kMaximaTarget, rgba8) uniform writeonly image2D target;
layout(push_constant) uniform Constants { MaximaConstants constants; };

vec4 fetchMaximaSource(ivec2 texel) { return imageLoad(source, texel); }

#include "cloud_weather_maxima.h"

void main() {
  const uvec2 cell = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(cell, uvec2(constants.targetSize)))) return;
  const vec2 maxima =
      weatherCellMaxima(ivec2(cell), int(constants.sourceSize), int(constants.cellSize));
  imageStore(target, ivec2(cell), vec4(maxima, 0.0f, 1.0f));
}
