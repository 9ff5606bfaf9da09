#include "components.h"

#include <cmath>

namespace sample {

glm::dvec3 forwardOf(const FlightCamera& camera) {
  const double cp = std::cos(camera.pitchRadians);
  return {-std::sin(camera.yawRadians) * cp, std::sin(camera.pitchRadians),
          -std::cos(camera.yawRadians) * cp};
}

glm::dvec3 directionOf(const SunLight& sun) {
  const double ce = std::cos(sun.elevationRadians);
  return {-std::sin(sun.azimuthRadians) * ce, std::sin(sun.elevationRadians),
          -std::cos(sun.azimuthRadians) * ce};
}

}  // namespace sample
