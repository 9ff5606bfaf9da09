#include "clouds/hero_cloud_life.h"

#include <algorithm>
#include <cmath>

namespace clouds {

HeroCloudLife heroCloudLife(const HeroCloudLifecycle& l, double seconds) {
  const double grow = l.growSeconds;
  const double mature = l.matureSeconds;
  const double dissipate = l.dissipateSeconds;
  const double period = grow + mature + dissipate + double(l.restSeconds);
  double age = seconds - l.startSeconds;
  if (age < 0.0) return {0.0f, 0.0f};
  // Repeating lives restart where the previous rest ended; the modulo is taken in double
  // precision, so hours of play keep sub-millisecond ages.
  if (l.repeat) age = std::fmod(age, period);
  if (age < grow) return {float(age / grow), 0.0f};
  age -= grow + mature;
  if (age < 0.0) return {1.0f, 0.0f};
  return {1.0f, float(std::min(age / dissipate, 1.0))};
}

namespace {

std::string outside(const char* field, double value, const char* range) {
  return std::string("HeroCloudLifecycle.") + field + " = " + std::to_string(value) +
         ": must be in " + range;
}

}  // namespace

std::string validateHeroCloudLifecycle(const HeroCloudLifecycle& l) {
  if (!std::isfinite(l.startSeconds)) return "HeroCloudLifecycle.startSeconds: must be finite";
  if (!(l.growSeconds >= 0.1f && l.growSeconds <= 1e6f)) {
    return outside("growSeconds", l.growSeconds, "[0.1, 1e6]");
  }
  if (!(l.matureSeconds >= 0.0f && l.matureSeconds <= 1e6f)) {
    return outside("matureSeconds", l.matureSeconds, "[0, 1e6]");
  }
  if (!(l.dissipateSeconds >= 0.1f && l.dissipateSeconds <= 1e6f)) {
    return outside("dissipateSeconds", l.dissipateSeconds, "[0.1, 1e6]");
  }
  if (!(l.restSeconds >= 0.0f && l.restSeconds <= 1e6f)) {
    return outside("restSeconds", l.restSeconds, "[0, 1e6]");
  }
  return {};
}

}  // namespace clouds
