#version 460
// Sky (compute): writes the scene's HDR colour for every pixel from the view ray: the sky
// gradient of the time of day and the sun (scene_constants.h). Later passes draw terrain and
// composite clouds over it. Output: an RGBA16F storage image. Input: SceneFrame (bindings.h).
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "scene_constants.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = kSkyFrameBinding, std140) uniform Frame { SceneFrame frame; };
layout(binding = kSkyColorBinding, rgba16f) uniform writeonly image2D outColor;

void main() {
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, frame.extent.xy))) return;
  const vec2 ndc = (vec2(pixel) + 0.5f) / vec2(frame.extent.xy) * 2.0f - 1.0f;
  const vec3 ray = normalize(frame.cameraForward.xyz +
                             ndc.x * frame.cameraRight.w * frame.cameraRight.xyz -
                             ndc.y * frame.cameraUp.w * frame.cameraUp.xyz);
  const vec3 colour = skyRadiance(ray, frame.sunDirection.xyz, frame.skyZenith.rgb,
                                  frame.skyHorizon.rgb, frame.skyGround.rgb,
                                  frame.sunIlluminance.rgb, frame.sunDirection.w);
  imageStore(outColor, ivec2(pixel), vec4(colour, 1.0f));
}
