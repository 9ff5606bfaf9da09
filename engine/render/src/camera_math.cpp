#include "engine/render/camera_math.h"

#include <cmath>

namespace engine::render {

glm::mat4 perspectiveReversedZ(float verticalFovRadians, float aspect, float nearMetres) {
  const float f = 1.0f / std::tan(verticalFovRadians * 0.5f);
  glm::mat4 m(0.0f);  // column-major: m[column][row]
  m[0][0] = f / aspect;
  m[1][1] = -f;  // Vulkan clip space has y down
  m[3][2] = nearMetres;
  m[2][3] = -1.0f;
  return m;
}

glm::mat4 lookTo(const glm::vec3& position, const glm::vec3& forward, const glm::vec3& up) {
  const glm::vec3 f = glm::normalize(forward);
  const glm::vec3 r = glm::normalize(glm::cross(f, up));
  const glm::vec3 u = glm::cross(r, f);
  glm::mat4 view(1.0f);
  view[0][0] = r.x;
  view[1][0] = r.y;
  view[2][0] = r.z;
  view[0][1] = u.x;
  view[1][1] = u.y;
  view[2][1] = u.z;
  view[0][2] = -f.x;
  view[1][2] = -f.y;
  view[2][2] = -f.z;
  view[3][0] = -glm::dot(r, position);
  view[3][1] = -glm::dot(u, position);
  view[3][2] = glm::dot(f, position);
  return view;
}

}  // namespace engine::render
