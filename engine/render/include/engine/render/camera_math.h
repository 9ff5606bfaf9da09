#pragma once
// Camera conventions shared by the engine: metres, Y up, right-handed view space looking down
// -Z, Vulkan clip space (y down, depth in [0, 1]) with reversed-Z (near = 1, infinity = 0).
#include <glm/glm.hpp>

namespace engine::render {

// Infinite-far reversed-Z perspective. `verticalFovRadians` in (0, pi), `aspect` = width /
// height, `nearMetres` > 0. Depth = near / distance along -Z.
glm::mat4 perspectiveReversedZ(float verticalFovRadians, float aspect, float nearMetres);

// World -> view for a camera at `position` looking along `forward` with `up` as a hint.
glm::mat4 lookTo(const glm::vec3& position, const glm::vec3& forward, const glm::vec3& up);

}  // namespace engine::render
