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
  // The sky's cosine-weighted mean radiance, times pi. For a sky mixed from horizon to zenith
  // by sqrt(sin(elevation)), as the sample's gradient sky is, that mean is exactly
  // 0.8 zenith + 0.2 horizon; for a measured sky it is an estimate from two of its regions.
  const glm::dvec3 skyRadiance = 0.8 * glm::dvec3(sky.zenith) + 0.2 * glm::dvec3(sky.horizon);
  const glm::dvec3 total =
      glm::dvec3(sunKilolux) * std::max(sunDirectionY, 0.0) + kPi * skyRadiance;
  return luminance(total);
}

float adaptEv100(float current, float target, double dtSeconds, double tauSeconds) {
  if (tauSeconds <= 0.0) return target;
  const double keep = std::exp(-std::max(dtSeconds, 0.0) / tauSeconds);
  return static_cast<float>(double(target) + (double(current) - double(target)) * keep);
}

}  // namespace engine::render
