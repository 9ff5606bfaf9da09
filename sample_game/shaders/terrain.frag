#version 460
// Terrain shading: albedo from the mesh's vertex colours (rock/grass/snow), sun (Lambert) and
// a hemisphere sky ambient, then exponential distance fog towards the sky behind the fragment
// (the hook the atmosphere will replace with aerial perspective). HDR, linear.
#extension GL_GOOGLE_include_directive : require
#include "scene_constants.h"

layout(binding = 0, std140) uniform Frame { SceneFrame frame; };
layout(location = 0) in vec3 inRelative;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 0) out vec4 outColor;

const float kInvPi = 0.318309886f;

void main() {
  const vec3 n = normalize(inNormal);
  const vec3 sun = frame.sunDirection.xyz;
  const vec3 direct = frame.sunIlluminance.rgb * (max(dot(n, sun), 0.0f) * kInvPi);
  const vec3 upperSky = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, 0.5f);
  const vec3 ambient = mix(frame.skyGround.rgb, upperSky, n.y * 0.5f + 0.5f);
  const vec3 lit = inColor * (direct + ambient);
  const float distance = length(inRelative);
  const vec3 view = inRelative / max(distance, 1e-3f);
  const vec3 sky = skyRadiance(view, sun, frame.skyZenith.rgb, frame.skyHorizon.rgb,
                               frame.skyGround.rgb, frame.sunIlluminance.rgb, 0.0f);
  const float transmittance = exp(-frame.fog.x * distance);
  outColor = vec4(mix(sky, lit, transmittance), 1.0f);
}
