#pragma once
// Camera conventions shared by the engine: metres, Y up, right-handed view space looking down
// -Z, Vulkan clip space (y down, depth in [0, 1]) with reversed-Z (near = 1, infinity = 0).
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace engine::render {

// Infinite-far reversed-Z perspective. `verticalFovRadians` in (0, pi), `aspect` = width /
// height, `nearMetres` > 0. Depth = near / distance along -Z.
glm::mat4 perspectiveReversedZ(float verticalFovRadians, float aspect, float nearMetres);

// World -> view for a camera at `position` looking along `forward` with `up` as a hint.
glm::mat4 lookTo(const glm::vec3& position, const glm::vec3& forward, const glm::vec3& up);

// The unit direction at `azimuthDegrees` (0 along -Z, counter-clockwise seen from above) and
// `elevationDegrees` (up positive): a camera's forward from its yaw and pitch, or the sun's.
glm::vec3 directionFromAngles(double azimuthDegrees, double elevationDegrees);

// Reversed-Z depth (near / view distance along -Z) of a flat ground at y = 0 seen from
// `heightMetres` above it, for a `width` x `height` image of a camera with `view` (rotation)
// and `projection` (perspectiveReversedZ with near `nearMetres`); 0 (the far plane) where a
// pixel sees no ground. Row-major, pixel centres. Tools and tests use it as a host's depth.
std::vector<float> flatGroundDepth(const glm::mat4& view, const glm::mat4& projection,
                                   float nearMetres, double heightMetres, std::uint32_t width,
                                   std::uint32_t height);

}  // namespace engine::render
