#version 460
// HUD text (Dear ImGui draw data): pixel-space positions to clip space, vertex colour and
// font-atlas UVs passed through.
layout(push_constant) uniform Constants { vec2 scale; vec2 translate; };
layout(location = 0) in vec2 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec4 inColor;
layout(location = 0) out vec2 outUv;
layout(location = 1) out vec4 outColor;

void main() {
  outUv = inUv;
  outColor = inColor;
  gl_Position = vec4(inPosition * scale + translate, 0.0f, 1.0f);
}
