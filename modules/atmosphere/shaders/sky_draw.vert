#version 460
// The sky drawn inside the host's scene pass (drawSky()): one triangle over the screen at the far
// plane, so that with the depth test EQUAL only the pixels the host's geometry left empty are
// shaded. Each corner carries its view ray; interpolated linearly in screen space (the ray is a
// linear function of the pixel), normalised per pixel by sky_draw.frag.
#extension GL_GOOGLE_include_directive : require
#define ATMOSPHERE_GRAPHICS
#include "atmosphere_types.h"
#include "atmosphere_model.h"

layout(constant_id = kSpecReversedZ) const uint kReversedZ = 1u;
#include "atmosphere_uniforms.glsl"

layout(location = 0) noperspective out vec3 outRay;
layout(location = 1) flat out uint outUniformIndex;

vec3 sampleTransmittance(vec2 uv) { return vec3(1.0); }
vec3 sampleMultiScattering(vec2 uv) { return vec3(0.0); }

void main() {
  loadUniformsAt(uint(gl_InstanceIndex));
  const vec2 ndc = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  const float far = kReversedZ != 0u ? 0.0 : 1.0;
  outRay = (u.clipToWorldRay * vec4(ndc, far, 1.0)).xyz;
  outUniformIndex = uint(gl_InstanceIndex);
  gl_Position = vec4(ndc, far, 1.0);
}
