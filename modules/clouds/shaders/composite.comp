#version 460
// Composite helper: applies the clouds over the host's colour image in place,
// colour = colour * transmittance + radiance. The march already stopped at the host's depth,
// so clouds behind geometry are absent and clouds in front cover it.
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(binding = kCompositeHostColor, rgba16f) uniform image2D hostColor;
layout(binding = kCompositeClouds, rgba16f) uniform readonly image2D cloudRadiance;
layout(push_constant) uniform Constants { CompositeConstants constants; };

void main() {
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, constants.extent.xy))) return;
  const vec4 clouds = imageLoad(cloudRadiance, ivec2(pixel));
  const vec4 color = imageLoad(hostColor, ivec2(pixel));
  // (Clamped: with god rays the clouds' rgb may take light from the sky behind them.)
  imageStore(hostColor, ivec2(pixel),
             vec4(max(color.rgb * clouds.a + clouds.rgb, vec3(0.0f)), color.a));
}
