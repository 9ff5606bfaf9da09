#version 460
// The water's surface: one square of kWaterReachMetres each way around the camera at the
// water's level (two triangles from the vertex index, no buffer), positions relative to the
// camera so precision stays where the viewer is. Reversed-Z with an infinite far plane: the far
// edge is past the horizon's haze.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "scene_constants.h"

layout(binding = kWaterFrameBinding, std140) uniform Frame { SceneFrame frame; };
layout(location = 0) out vec3 outRelative;  // position relative to the camera (m)

void main() {
  const vec2 corners[6] = vec2[](vec2(-1.0f, -1.0f), vec2(1.0f, -1.0f), vec2(1.0f, 1.0f),
                                 vec2(-1.0f, -1.0f), vec2(1.0f, 1.0f), vec2(-1.0f, 1.0f));
  const vec2 corner = corners[gl_VertexIndex] * kWaterReachMetres;
  const vec3 relative = vec3(corner.x, frame.water.x - frame.cameraPosition.y, corner.y);
  outRelative = relative;
  gl_Position = frame.viewProjection * vec4(relative, 1.0f);
}
