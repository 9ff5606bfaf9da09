#pragma once
// Where the sun is for the god-ray mask (fxcontracts/god_rays.h), from the host's camera: its
// position on screen in the mask's uv and the fade, pure arithmetic (unit-tested). The fade is 1
// with the sun on screen and 1 degree or more above the horizon, falls to 0 as it leaves the screen
// by half of it or sinks to 1 degree below the horizon, and is 0 behind the camera.
#include <glm/glm.hpp>

#include "clouds/clouds.h"

namespace clouds::detail {

struct GodRaySun {
  glm::vec2 uv{0.5f};  // on screen: [0, 1] (y down, as pixels), clamped to [-4, 5]
  float fade = 0.0f;   // [0, 1]
};

GodRaySun godRaySun(const glm::mat4& view, const glm::mat4& projection,
                    const glm::vec3& sunDirection);

}  // namespace clouds::detail
