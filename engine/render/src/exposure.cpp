#include "engine/render/exposure.h"

#include <algorithm>
#include <cmath>

#include "engine/render/scene_components.h"

namespace engine::render {

namespace {
constexpr double kMeterCalibration = 250.0;  // C of an incident-light meter, lx s (ISO 2720)
constexpr double kPi = 3.14159265358979;
}  // namespace

float ev100FromIlluminance(double lux) {
  return static_cast<float>(std::log2(std::max(lux, 1e-3) * 100.0 / kMeterCalibration));
}

float dimLightCompensationEv(float meteredEv100) {
  constexpr float kDaylightEv = 10.0f;
  constexpr float kStopsPerEv = 0.3f;  // -3 stops at EV100 0
  return -kStopsPerEv * std::clamp(kDaylightEv - meteredEv100, 0.0f, kDaylightEv);
}

float exposureScale(float ev100) {
  return static_cast<float>(1000.0 / (1.2 * std::exp2(double(ev100))));
}

double horizontalIlluminanceKilolux(const glm::vec3& sunKilolux, double sunDirectionY,
                                    const SkyLight& sky) {
  return horizontalIlluminanceKilolux(sunKilolux, sunDirectionY, sky, nullptr, 0.0);
}

double horizontalIlluminanceKilolux(const glm::vec3& sunKilolux, double sunDirectionY,
                                    const SkyLight& clear, const CoveredSkyLight* covered,
                                    double altitudeMetres) {
  // The sky's cosine-weighted mean radiance, times pi. For a sky mixed from horizon to zenith
  // by sqrt(sin(elevation)), as the sample's gradient sky is, that mean is exactly
  // 0.8 zenith + 0.2 horizon; for a measured sky it is an estimate from two of its regions.
  glm::dvec3 skyOverPi = 0.8 * glm::dvec3(clear.zenith) + 0.2 * glm::dvec3(clear.horizon);
  double sunShare = 1.0;
  if (covered != nullptr) {
    // Inside the cover the meter sees some of it above and some below: a linear blend by
    // altitude, an approximation (the cover's own light around the meter is not measured).
    const double span = std::max(covered->clearAboveMetres - covered->seenFromMetres, 1.0);
    const double clearShare =
        std::clamp((altitudeMetres - covered->seenFromMetres) / span, 0.0, 1.0);
    skyOverPi = glm::mix(glm::dvec3(covered->irradianceOverPi), skyOverPi, clearShare);
    // Under the cover, centre-weighted with the land around; above it, what the camera sees is
    // lit as the camera is.
    const double atCamera = std::clamp(double(covered->sunAtCamera), 0.0, 1.0);
    const double around = std::clamp(double(covered->sunAround), 0.0, 1.0);
    sunShare = std::lerp(0.5 * (atCamera + around), atCamera, clearShare);
  }
  const glm::dvec3 total =
      glm::dvec3(sunKilolux) * (std::max(sunDirectionY, 0.0) * sunShare) + kPi * skyOverPi;
  return luminance(total);
}

float adaptEv100(float current, float target, double dtSeconds, double tauSeconds) {
  if (tauSeconds <= 0.0) return target;
  const double keep = std::exp(-std::max(dtSeconds, 0.0) / tauSeconds);
  return static_cast<float>(double(target) + (double(current) - double(target)) * keep);
}

}  // namespace engine::render
