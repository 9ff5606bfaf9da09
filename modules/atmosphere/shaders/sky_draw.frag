#version 460
// The sky and the sun's disc for one pixel the host's geometry left empty (sky_draw.vert), as
// apply.comp draws them: the same skyWithSun().
#extension GL_GOOGLE_include_directive : require
#define ATMOSPHERE_GRAPHICS
#include "atmosphere_types.h"
#include "atmosphere_model.h"
#include "atmosphere_uniforms.glsl"
layout(binding = kBindingSkyView) uniform sampler2D skyViewLut;

layout(location = 0) noperspective in vec3 inRay;
// 0; not a constant, so the uniform loads stay dynamic (atmosphere_uniforms.glsl).
layout(location = 1) flat in uint inUniformIndex;
layout(location = 0) out vec4 outColor;

vec3 sampleTransmittance(vec2 uv) { return vec3(1.0); }
vec3 sampleMultiScattering(vec2 uv) { return vec3(0.0); }
#include "sky_radiance.glsl"

void main() {
  loadUniformsAt(inUniformIndex);
  outColor = vec4(skyWithSun(normalize(inRay)), 1.0);
}
