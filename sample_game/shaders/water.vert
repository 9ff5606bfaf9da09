#version 460
// The water's surface at its level, positions relative to the camera so precision stays where
// the viewer is (reversed-Z, infinite far plane: the far edge is past the horizon's haze), in
// two parts from the vertex index, no buffer: vertices 0-5 the square within the bed's reach
// around the camera (waterBedReachMetres(): SceneFrame::water.z), where the bed shows through,
// drawn after the terrain; vertices 6-29 the four rectangles from it out to kWaterReachMetres,
// where it does not, drawn before the terrain so that the bed beneath is never shaded.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "scene_constants.h"

layout(binding = kWaterFrameBinding, std140) uniform Frame { SceneFrame frame; };
layout(location = 0) out vec3 outRelative;  // position relative to the camera (m)

void main() {
  // Two triangles per rectangle, its corners in [0, 1]^2.
  const vec2 corners[6] = vec2[](vec2(0.0f, 0.0f), vec2(1.0f, 0.0f), vec2(1.0f, 1.0f),
                                 vec2(0.0f, 0.0f), vec2(1.0f, 1.0f), vec2(0.0f, 1.0f));
  const float near = frame.water.z;
  const float far = kWaterReachMetres;
  // The rectangles (lowest x and z, highest x and z): the near square, then the far ring's
  // south, north, west and east parts.
  const vec4 rectangles[5] = vec4[](vec4(-near, -near, near, near), vec4(-far, -far, far, -near),
                                    vec4(-far, near, far, far), vec4(-far, -near, -near, near),
                                    vec4(near, -near, far, near));
  const vec4 r = rectangles[gl_VertexIndex / 6];
  const vec2 xz = mix(r.xy, r.zw, corners[gl_VertexIndex % 6]);
  const vec3 relative = vec3(xz.x, frame.water.x - frame.cameraPosition.y, xz.y);
  outRelative = relative;
  gl_Position = frame.viewProjection * vec4(relative, 1.0f);
}
