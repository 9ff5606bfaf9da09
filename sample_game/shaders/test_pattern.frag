#version 460
// Test pattern fragment stage: flat HDR colour with a checker so orientation is visible.
layout(location = 0) in vec3 inColor;
layout(location = 0) out vec4 outColor;

void main() {
  const ivec2 cell = ivec2(gl_FragCoord.xy) / 8;
  const float checker = ((cell.x + cell.y) & 1) == 0 ? 1.0f : 0.7f;
  outColor = vec4(inColor * checker, 1.0f);
}
