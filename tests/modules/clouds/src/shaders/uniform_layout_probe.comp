#version 460
// Declares the module's uniform block exactly as its passes do (frame_uniforms.glsl), so that
// glslang's reflection of it can be compared with the C++ struct (uniform_layout_test.cpp).
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = 1) in;
#include "frame_uniforms.glsl"
layout(binding = 1, std430) buffer Out { float value; };

void main() {
  loadFrameUniforms();
  value = u.cameraAltitudeMetres;
}
