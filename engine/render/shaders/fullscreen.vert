#version 460
// Full-screen triangle from gl_VertexIndex (no vertex buffer). Outputs uv in [0,1], y down.
layout(location = 0) out vec2 outUv;

void main() {
  const vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  outUv = uv;
  gl_Position = vec4(uv * 2.0f - 1.0f, 0.0f, 1.0f);
}
