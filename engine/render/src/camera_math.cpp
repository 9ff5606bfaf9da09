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

glm::vec3 directionFromAngles(double azimuthDegrees, double elevationDegrees) {
  const double a = glm::radians(azimuthDegrees);
  const double e = glm::radians(elevationDegrees);
  return glm::vec3(glm::dvec3(-std::sin(a) * std::cos(e), std::sin(e), -std::cos(a) * std::cos(e)));
}

std::vector<float> flatGroundDepth(const glm::mat4& view, const glm::mat4& projection,
                                   float nearMetres, double heightMetres, std::uint32_t width,
                                   std::uint32_t height) {
  const glm::mat4 inverseProjection = glm::inverse(projection);
  const glm::mat3 viewToWorld = glm::transpose(glm::mat3(view));
  const glm::vec3 forward = -glm::vec3(viewToWorld[2]);
  std::vector<float> depth(std::size_t{width} * height, 0.0f);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const glm::vec2 ndc = (glm::vec2(x, y) + 0.5f) / glm::vec2(width, height) * 2.0f - 1.0f;
      const glm::vec4 p = inverseProjection * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 direction = glm::normalize(viewToWorld * (glm::vec3(p) / p.w));
      if (direction.y >= -1e-4f) continue;
      const double distance = heightMetres / -double(direction.y);
      depth[std::size_t{y} * width + x] =
          static_cast<float>(nearMetres / (distance * double(glm::dot(direction, forward))));
    }
  }
  return depth;
}

}  // namespace engine::render
