#pragma once
// Where the wind has carried the clouds' noise by a frame (x, z metres): what the host passed
// (the integral of a wind that changes), else the frame's time x the settings' wind. The noise
// placement, the history's reprojection and the shadow map's drift all read this one value.
#include <glm/glm.hpp>

#include "clouds/clouds.h"

namespace clouds::detail {

inline glm::dvec2 windDisplacementOf(const FrameInputs& in, const Settings& s) {
  if (in.windDisplacementMetres) return *in.windDisplacementMetres;
  return glm::normalize(glm::dvec2(s.windDirection)) *
         (static_cast<double>(s.windSpeedMetresPerSecond) * in.timeSeconds);
}

}  // namespace clouds::detail
