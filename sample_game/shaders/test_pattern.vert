#version 460
// Test pattern (graphics): three coloured quads at different depths, spinning slowly, drawn
// with reversed-Z depth testing over the sky. Vertices come from gl_VertexIndex (6 per quad).
#extension GL_GOOGLE_include_directive : require
#include "first_frame_constants.h"

layout(push_constant) uniform Constants { TestPatternConstants constants; };
layout(location = 0) out vec3 outColor;

void main() {
  const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1),
                                 vec2(-1, 1));
  const vec3 colors[3] = vec3[](vec3(4.0f, 0.3f, 0.2f), vec3(0.3f, 3.0f, 0.4f),
                                vec3(0.3f, 0.5f, 4.0f));
  const int quad = gl_VertexIndex / 6;
  const vec2 corner = corners[gl_VertexIndex % 6];
  const float angle = constants.params.x * 0.5f + float(quad) * 2.0944f;
  const float c = cos(angle);
  const float s = sin(angle);
  // Quads 2 m wide, centred 1 m apart around a point 10 m ahead of the origin along -Z.
  const vec3 centre = vec3(float(quad - 1) * 1.2f, 0.0f, -10.0f + float(quad) * 1.5f);
  const vec3 position = centre + vec3(corner.x * c - corner.y * s, corner.x * s + corner.y * c, 0.0f);
  outColor = colors[quad];
  gl_Position = constants.viewProjection * vec4(position, 1.0f);
}
