#version 460
// Terrain (graphics) in a scene with an atmosphere: the transform of terrain.vert, plus the
// aerial perspective read once per vertex and interpolated. The haze varies smoothly over a
// terrain triangle (tens of metres across), and a 3D lookup per fragment costs about as much as
// the rest of the terrain pass on a CPU rasteriser.
#extension GL_GOOGLE_include_directive : require
#include "scene_constants.h"
#include "vkfx/aerial_perspective.glsl"

layout(binding = 0, std140) uniform Frame { SceneFrame frame; };
layout(binding = 1) uniform sampler3D aerialPerspective;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outColor;
layout(location = 2) out vec4 outHaze;  // rgb in-scattered (kcd/m^2), a transmittance

void main() {
  const vec3 relative = inPosition - frame.cameraPosition.xyz;
  const vec4 clip = frame.viewProjection * vec4(relative, 1.0f);
  // Off-screen vertices (and those behind the camera, which are near it and barely hazed) read
  // the volume's edge.
  const vec2 uv = clamp(clip.xy / max(clip.w, 1e-6f) * 0.5f + 0.5f, 0.0f, 1.0f);
  const vec4 haze =
      aerialPerspectiveAt(aerialPerspective, uv, length(relative), frame.fog.y, frame.fog.z);
  outHaze = vec4(haze.rgb * frame.sunAboveAir.rgb, haze.a);
  outNormal = inNormal;
  outColor = inColor;
  gl_Position = clip;
}
