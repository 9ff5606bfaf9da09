#version 460
// Procedural sky gradient (compute): writes linear HDR sky radiance for each pixel's view ray,
// a zenith-to-horizon blend with a warm horizon band, a dark ground, and a sun disc with a
// glow. A stand-in until the atmosphere and clouds arrive; it proves the compute path.
// Output: binding 0, RGBA16F storage image. Push constants: SkyGradientConstants.
#extension GL_GOOGLE_include_directive : require
#include "first_frame_constants.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly image2D outColor;
layout(push_constant) uniform Constants { SkyGradientConstants constants; };

void main() {
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, constants.extent))) return;

  const vec2 ndc = (vec2(pixel) + 0.5f) / vec2(constants.extent) * 2.0f - 1.0f;
  const vec3 ray = normalize(constants.cameraForward.xyz +
                             ndc.x * constants.cameraRight.w * constants.cameraRight.xyz -
                             ndc.y * constants.cameraUp.w * constants.cameraUp.xyz);
  const float up = ray.y;
  const vec3 zenith = vec3(0.12f, 0.32f, 0.85f);
  const vec3 horizon = vec3(0.75f, 0.82f, 0.95f);
  const vec3 ground = vec3(0.18f, 0.16f, 0.14f);
  vec3 color = up >= 0.0f ? mix(horizon, zenith, pow(up, 0.5f))
                          : mix(horizon * 0.6f, ground, clamp(-up * 8.0f, 0.0f, 1.0f));
  const float sunCos = dot(ray, constants.sunDirection.xyz);
  const float glow = pow(max(sunCos, 0.0f), 64.0f) * 2.0f;
  const float disc = smoothstep(0.9995f, 0.9998f, sunCos) * constants.sunDirection.w;
  color += vec3(1.0f, 0.9f, 0.7f) * (glow + disc);
  imageStore(outColor, ivec2(pixel), vec4(color, 1.0f));
}
