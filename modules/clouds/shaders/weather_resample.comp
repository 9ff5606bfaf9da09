#version 460
// Resamples a host-painted weather map (any size, bilinear) into the module's 512^2 map, so
// an artist can paint coverage/type/density ("put a hole here"), blended towards a second
// painting by the push constants' weight (FrameInputs::weatherBlend; the same painting twice
// and weight 0 without one).
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(binding = kResampleTarget, rgba8) uniform writeonly image2D target;
layout(binding = kResampleSource) uniform sampler2D source;
layout(binding = kResampleBlendSource) uniform sampler2D blendSource;
layout(push_constant) uniform Constants { ResampleConstants constants; };

void main() {
  const uvec2 texel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(texel, uvec2(kWeatherMapSize)))) return;
  const vec2 uv = (vec2(texel) + 0.5f) / float(kWeatherMapSize);
  const vec4 painted = textureLod(source, uv, 0.0f);
  const vec4 blended = constants.blend > 0.0f
                           ? mix(painted, textureLod(blendSource, uv, 0.0f), constants.blend)
                           : painted;
  imageStore(target, ivec2(texel), clamp(blended, 0.0f, 1.0f));
}
