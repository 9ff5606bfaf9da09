#version 460
// Test probe: out[i] = f(i) for a function the C++ test evaluates too; SCALE is a
// specialization constant so the test also proves specialization reaches the shader.
layout(local_size_x = 64) in;
layout(constant_id = 0) const float SCALE = 1.0f;
layout(binding = 0, std430) writeonly buffer Output { float values[]; };
layout(push_constant) uniform Constants { uint count; };

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  const float x = float(i) * 0.01f;
  values[i] = SCALE * (sin(x) * x + sqrt(x) + exp(-x));
}
