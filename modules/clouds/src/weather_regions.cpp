#include "weather_regions.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace clouds::detail {
namespace {

// The look fields a region sets, with their ranges (clouds.h, WeatherRegion).
struct LookField {
  float WeatherRegion::*field;
  float lo;
  float hi;
  bool relative;  // its change is measured against its value, not its range
};
constexpr LookField kLookFields[] = {{&WeatherRegion::coverage, 0.0f, 1.0f, false},
                                     {&WeatherRegion::cloudType, 0.0f, 1.0f, false},
                                     {&WeatherRegion::densityMultiplier, 0.0f, 1e6f, true},
                                     {&WeatherRegion::anvilBias, 0.0f, 1.0f, false}};

// How far a superstorm changed: its eye and wall (in blend distances), its speed and arms
// (relative); 1 when one of the two has none.
float vortexChange(const WeatherRegion& a, const WeatherRegion& b) {
  const WeatherRegion::Vortex& va = a.vortex;
  const WeatherRegion::Vortex& vb = b.vortex;
  if ((va.eyeRadiusMetres > 0.0f) != (vb.eyeRadiusMetres > 0.0f)) return 1.0f;
  const float blend = std::max(std::min(a.blendMetres, b.blendMetres), 1.0f);
  const float size = std::abs(va.eyeRadiusMetres - vb.eyeRadiusMetres) +
                     std::abs(va.eyeWallMetres - vb.eyeWallMetres);
  const float speed = std::abs(va.wallSpeedMetresPerSecond - vb.wallSpeedMetresPerSecond) /
                      std::max({std::abs(va.wallSpeedMetresPerSecond),
                                std::abs(vb.wallSpeedMetresPerSecond), 1.0f});
  const float arms = std::abs(va.spiralArms - vb.spiralArms) / 8.0f;
  return std::max({size / blend, speed, arms});
}

float lookChange(const WeatherRegion& a, const WeatherRegion& b) {
  float change = 0.0f;
  for (const LookField& f : kLookFields) {
    const float delta = std::abs(a.*f.field - b.*f.field);
    const float scale =
        f.relative ? std::max({std::abs(a.*f.field), std::abs(b.*f.field), 1e-3f}) : f.hi - f.lo;
    change = std::max(change, delta / scale);
  }
  return change;
}

// How far the region's edge moved, in blend distances: its centre, its sides and radius, and
// its turn at the far corner of its core.
float placeChange(const WeatherRegion& a, const WeatherRegion& b) {
  const double blend = std::max(std::min(a.blendMetres, b.blendMetres), 1.0f);
  const double centre = glm::length(a.centreMetres - b.centreMetres);
  const double sides = glm::length(glm::dvec2(a.halfSidesMetres - b.halfSidesMetres));
  const double radius = std::abs(double(a.radiusMetres) - double(b.radiusMetres));
  const double widths = std::abs(double(a.blendMetres) - double(b.blendMetres));
  const double reach = glm::length(glm::dvec2(glm::max(a.halfSidesMetres, b.halfSidesMetres)));
  const double turn =
      std::abs(glm::radians(double(a.headingDegrees) - double(b.headingDegrees))) * reach;
  return static_cast<float>(std::max({centre + sides + radius, widths, turn}) / blend);
}

}  // namespace

bool hasVortex(std::span<const WeatherRegion> regions) {
  return std::any_of(regions.begin(), regions.end(),
                     [](const WeatherRegion& r) { return r.vortex.eyeRadiusMetres > 0.0f; });
}

glm::vec4 vortexClock(const WeatherRegion& storm, double seconds) {
  const WeatherRegion::Vortex& v = storm.vortex;
  const double wall = double(v.eyeRadiusMetres) + 0.5 * double(v.eyeWallMetres);
  const double rate = double(v.wallSpeedMetresPerSecond) / std::max(wall, 1.0);  // rad/s
  const double period =
      std::clamp(0.5 * glm::pi<double>() / std::max(std::abs(rate), 1e-9), 10.0, 3600.0);
  const double a = seconds / period - std::floor(seconds / period);  // [0, 1)
  const double b = a < 0.5 ? a + 0.5 : a - 0.5;
  return {float(a * period), float(b * period), float(1.0 - std::abs(2.0 * a - 1.0)), 0.0f};
}

float fullestCoverage(const Settings& s, std::span<const WeatherRegion> regions) {
  // A superstorm's wall is full (vortexLook()).
  float fullest = hasVortex(regions) ? 1.0f : s.coverage;
  for (const WeatherRegion& r : regions) fullest = std::max(fullest, r.coverage);
  return fullest;
}

float densestMultiplier(const Settings& s, std::span<const WeatherRegion> regions) {
  float densest = s.densityMultiplier;
  for (const WeatherRegion& r : regions) densest = std::max(densest, r.densityMultiplier);
  return densest;
}

void setWeatherRegions(shader::CloudUniforms& u, const FrameInputs& in, const Settings& s) {
  const std::span<const WeatherRegion> regions = in.weatherRegions.first(
      std::min<std::size_t>(in.weatherRegions.size(), shader::kMaxWeatherRegions));
  const float densest = densestMultiplier(s, regions);
  // A column's density scale: its multiplier over the densest (x / x is exactly 1, so a frame
  // without regions marches the bits it did before regions existed).
  const auto scale = [densest](float multiplier) {
    return densest > 0.0f ? multiplier / densest : 1.0f;
  };
  u.extinctionPerMetre = s.extinctionPerMetre * densest;
  u.layerDensityScale = scale(s.densityMultiplier);
  u.fullestCoverage = fullestCoverage(s, regions);
  u.weatherRegionCount = static_cast<std::uint32_t>(regions.size());
  u.vortexRegion = shader::kNoVortex;
  const glm::dvec2 camera(in.cameraPosition.x, in.cameraPosition.z);
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const WeatherRegion& r = regions[i];
    // About the camera in double precision: far from the origin the shaders see small numbers.
    const glm::vec2 centre(r.centreMetres - camera);
    const double heading = glm::radians(static_cast<double>(r.headingDegrees));
    shader::WeatherRegionUniform& out = u.weatherRegions[i];
    out.placement = glm::vec4(centre, r.halfSidesMetres);
    out.shape = glm::vec4(static_cast<float>(std::cos(heading)),
                          static_cast<float>(-std::sin(heading)), r.radiusMetres, r.blendMetres);
    out.look = glm::vec4(r.coverage, r.cloudType, scale(r.densityMultiplier), r.anvilBias);
    const WeatherRegion::Vortex& v = r.vortex;
    out.vortex = glm::vec4(0.0f);
    if (v.eyeRadiusMetres > 0.0f) {
      const float wall = v.eyeRadiusMetres + 0.5f * v.eyeWallMetres;
      out.vortex = glm::vec4(v.eyeRadiusMetres, v.eyeWallMetres, v.wallSpeedMetresPerSecond / wall,
                             v.spiralArms);
      u.vortexRegion = static_cast<std::uint32_t>(i);
      u.vortexClock = vortexClock(r, in.timeSeconds);
    }
  }
}

float weatherRegionsChange(std::span<const WeatherRegion> a, std::span<const WeatherRegion> b) {
  if (a.size() != b.size()) return 1.0f;
  float change = 0.0f;
  for (std::size_t i = 0; i < a.size(); ++i) {
    change = std::max(
        {change, lookChange(a[i], b[i]), placeChange(a[i], b[i]), vortexChange(a[i], b[i])});
  }
  return change;
}

std::vector<WeatherRegion> leadRegions(std::span<const WeatherRegion> now,
                                       std::span<const WeatherRegion> before, float frames) {
  std::vector<WeatherRegion> led(now.begin(), now.end());
  if (before.size() != now.size()) return led;
  for (std::size_t i = 0; i < led.size(); ++i) {
    for (const LookField& f : kLookFields) {
      const float change = now[i].*f.field - before[i].*f.field;
      led[i].*f.field = std::clamp(now[i].*f.field + frames * change, f.lo, f.hi);
    }
  }
  return led;
}

}  // namespace clouds::detail
