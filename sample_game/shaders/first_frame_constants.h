// Push constants of the sample's first passes (procedural sky and test pattern), shared by the
// shaders and the C++ that fills them.
#ifndef SAMPLE_SHADERS_FIRST_FRAME_CONSTANTS_H
#define SAMPLE_SHADERS_FIRST_FRAME_CONSTANTS_H

#include "interop.h"

SHADER_NAMESPACE_BEGIN

struct SkyGradientConstants {
  vec4 cameraRight;    // xyz world direction; w = tan(horizontal fov / 2)
  vec4 cameraUp;       // xyz; w = tan(vertical fov / 2)
  vec4 cameraForward;  // xyz; w unused
  vec4 sunDirection;   // xyz towards the sun (unit); w = sun disc radiance scale
  uvec2 extent;        // output size in pixels; 0 means nothing to do
  float timeSeconds;
  float pad0;
};
SHADER_STATIC_ASSERT(sizeof(SkyGradientConstants) == 80);

struct TestPatternConstants {
  mat4 viewProjection;  // world -> clip, reversed-Z
  vec4 params;          // x = time in seconds, yzw unused
};
SHADER_STATIC_ASSERT(sizeof(TestPatternConstants) == 80);

SHADER_NAMESPACE_END

#endif
