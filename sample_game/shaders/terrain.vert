#version 460
// Terrain (graphics): camera-relative transform of the terrain mesh (positions in world
// metres; the camera position is subtracted before projecting so precision stays where the
// viewer is). Reversed-Z depth.
#extension GL_GOOGLE_include_directive : require
#include "scene_constants.h"

layout(binding = 0, std140) uniform Frame { SceneFrame frame; };
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 0) out vec3 outRelative;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outColor;

void main() {
  const vec3 relative = inPosition - frame.cameraPosition.xyz;
  outRelative = relative;
  outNormal = inNormal;
  outColor = inColor;
  gl_Position = frame.viewProjection * vec4(relative, 1.0f);
}
