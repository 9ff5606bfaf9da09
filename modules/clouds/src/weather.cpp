#include "clouds/weather.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <sstream>

#include "cloud_weather_regions.h"
#include "weather_regions.h"

namespace clouds {
namespace {

// Smoothstep: the blend's ease, flat at both ends so that no field changes speed abruptly.
double ease(double u) {
  return u * u * (3.0 - 2.0 * u);
}
// Its integral from 0 to u: what a velocity blended by it carries the clouds.
double easeIntegral(double u) {
  return u * u * u - 0.5 * u * u * u * u;
}

constexpr double kMaxKeySeconds = 1e7;

struct Preset {
  WeatherPreset preset;
  const char* name;
  WeatherState state;
};

WeatherState makeState(float coverage, float type, float density, float anvil, float erosion,
                       float windSpeed, float skew, float shear, float strikes) {
  WeatherState s;
  s.coverage = coverage;
  s.cloudType = type;
  s.densityMultiplier = density;
  s.anvilBias = anvil;
  s.detailErosion = erosion;
  s.windSpeedMetresPerSecond = windSpeed;
  s.skewMetres = skew;
  s.windShearDegrees = shear;
  s.lightningStrikesPerMinute = strikes;
  return s;
}

// HDRP's four, in Nubis's terms: fair-weather cumulus scattered over a clear sky; a broken
// cumulus and stratocumulus sky; a low, grey stratus deck with little relief; towering
// cumulonimbus with anvils, dense enough to go dark, leaning in a stronger wind that veers
// with height (its tops lean the way the upper wind blows), striking.
const Preset kPresets[] = {
    {WeatherPreset::Sparse, "sparse",
     makeState(0.5f, 0.9f, 1.0f, 0.0f, 0.5f, 8.0f, 400.0f, 0.0f, 0)},
    {WeatherPreset::Cloudy, "cloudy",
     makeState(0.6f, 0.7f, 1.0f, 0.0f, 0.45f, 12.0f, 500.0f, 0.0f, 0)},
    {WeatherPreset::Overcast, "overcast",
     makeState(0.9f, 0.15f, 1.5f, 0.0f, 0.3f, 15.0f, 300.0f, 0.0f, 0)},
    {WeatherPreset::Stormy, "stormy",
     makeState(0.65f, 1.0f, 4.0f, 1.0f, 0.35f, 18.0f, 1500.0f, 40.0f, 12)},
};

const Preset& presetOf(WeatherPreset preset) {
  const auto* found = std::find_if(std::begin(kPresets), std::end(kPresets),
                                   [&](const Preset& p) { return p.preset == preset; });
  return found != std::end(kPresets) ? *found : kPresets[1];
}

std::string timeError(std::size_t key, const char* field, double value) {
  std::ostringstream out;
  out << "WeatherKey[" << key << "]." << field << " = " << value << ": must be in [0, "
      << kMaxKeySeconds << "]";
  return out.str();
}

}  // namespace

WeatherState weatherPreset(WeatherPreset preset) {
  return presetOf(preset).state;
}

const char* weatherPresetName(WeatherPreset preset) {
  return presetOf(preset).name;
}

bool parseWeatherPreset(std::string_view name, WeatherPreset* preset) {
  for (const Preset& p : kPresets) {
    const std::string_view candidate = p.name;
    const bool same = candidate.size() == name.size() &&
                      std::equal(name.begin(), name.end(), candidate.begin(), [](char a, char b) {
                        return std::tolower(static_cast<unsigned char>(a)) == b;
                      });
    if (same) {
      *preset = p.preset;
      return true;
    }
  }
  return false;
}

WeatherState weatherOf(const Settings& s) {
  WeatherState w;
  w.coverage = s.coverage;
  w.cloudType = s.cloudType;
  w.densityMultiplier = s.densityMultiplier;
  w.anvilBias = s.anvilBias;
  w.detailErosion = s.detailErosion;
  w.windDirection = s.windDirection;
  w.windSpeedMetresPerSecond = s.windSpeedMetresPerSecond;
  w.skewMetres = s.skewMetres;
  w.windShearDegrees = s.windShearDegrees;
  return w;
}

Settings withWeather(Settings s, const WeatherState& w) {
  s.coverage = w.coverage;
  s.cloudType = w.cloudType;
  s.densityMultiplier = w.densityMultiplier;
  s.anvilBias = w.anvilBias;
  s.detailErosion = w.detailErosion;
  s.windDirection = w.windDirection;
  s.windSpeedMetresPerSecond = w.windSpeedMetresPerSecond;
  s.skewMetres = w.skewMetres;
  s.windShearDegrees = w.windShearDegrees;
  return s;
}

float weatherRegionStrength(const WeatherRegion& region, glm::dvec2 xzMetres) {
  // The shaders' own function, with the column at the uniforms' origin.
  FrameInputs at;
  at.cameraPosition = glm::dvec3(xzMetres.x, 0.0, xzMetres.y);
  at.weatherRegions = std::span(&region, 1);
  shader::CloudUniforms u{};
  detail::setWeatherRegions(u, at, Settings{});
  const shader::WeatherRegionUniform& r = u.weatherRegions[0];
  return shader::regionStrength(shader::regionCoreDistance(glm::vec2(0.0f), r), r);
}

WeatherState weatherAt(const WeatherState& surrounding, std::span<const WeatherRegion> regions,
                       std::span<const WeatherState> states, glm::dvec2 xzMetres) {
  WeatherState weather = surrounding;
  for (std::size_t i = 0; i < std::min(regions.size(), states.size()); ++i) {
    const float strength = weatherRegionStrength(regions[i], xzMetres);
    if (strength > 0.0f) weather = blendWeather(weather, states[i], strength);
  }
  return weather;
}

WeatherRegion withWeather(WeatherRegion region, const WeatherState& state) {
  region.coverage = state.coverage;
  region.cloudType = state.cloudType;
  region.densityMultiplier = state.densityMultiplier;
  region.anvilBias = state.anvilBias;
  return region;
}

std::string validateWeatherState(const WeatherState& w) {
  // The shared fields have Settings' ranges: check them there and name them here.
  const std::string error = validateSettings(withWeather(Settings{}, w));
  if (!error.empty()) {
    const std::string_view prefix = "Settings.";
    return error.starts_with(prefix) ? "WeatherState." + error.substr(prefix.size()) : error;
  }
  const float strikes = w.lightningStrikesPerMinute;
  if (!(std::isfinite(strikes) && strikes >= 0.0f && strikes <= 600.0f)) {
    std::ostringstream out;
    out << "WeatherState.lightningStrikesPerMinute = " << strikes << ": must be in [0, 600]";
    return out.str();
  }
  return {};
}

glm::dvec2 windVelocity(const WeatherState& w) {
  const glm::dvec2 direction(w.windDirection);
  const double length = glm::length(direction);
  if (!(length > 0.0) || !std::isfinite(length)) return glm::dvec2(0.0);
  return direction / length * static_cast<double>(w.windSpeedMetresPerSecond);
}

WeatherState blendWeather(const WeatherState& a, const WeatherState& b, float t) {
  const auto mix = [t](float x, float y) { return x + (y - x) * t; };
  WeatherState w;
  w.coverage = mix(a.coverage, b.coverage);
  w.cloudType = mix(a.cloudType, b.cloudType);
  w.densityMultiplier = mix(a.densityMultiplier, b.densityMultiplier);
  w.anvilBias = mix(a.anvilBias, b.anvilBias);
  w.detailErosion = mix(a.detailErosion, b.detailErosion);
  w.skewMetres = mix(a.skewMetres, b.skewMetres);
  w.windShearDegrees = mix(a.windShearDegrees, b.windShearDegrees);
  w.lightningStrikesPerMinute = mix(a.lightningStrikesPerMinute, b.lightningStrikesPerMinute);
  // The wind as a velocity, so that the displacement (its integral) has a closed form.
  const glm::dvec2 velocity = glm::mix(windVelocity(a), windVelocity(b), double(t));
  const double speed = glm::length(velocity);
  w.windSpeedMetresPerSecond = static_cast<float>(speed);
  // A calm in between keeps a direction (the one it blows towards next).
  w.windDirection = speed > 1e-9 ? glm::vec2(velocity / speed) : (t < 0.5f ? a : b).windDirection;
  return w;
}

WeatherTimeline::WeatherTimeline(const WeatherState& state) {
  keys_.push_back(WeatherKey{state, 0.0, 0.0});
  measure();
}

std::optional<WeatherTimeline> WeatherTimeline::schedule(std::span<const WeatherKey> keys,
                                                         bool repeat, std::string* error) {
  const auto fail = [&](std::string message) -> std::optional<WeatherTimeline> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  if (keys.empty()) return fail("a weather schedule needs at least one state");
  double total = 0.0;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const WeatherKey& key = keys[i];
    if (std::string problem = validateWeatherState(key.state); !problem.empty()) {
      return fail("WeatherKey[" + std::to_string(i) + "]: " + problem);
    }
    for (const auto& [field, value] : {std::pair{"holdSeconds", key.holdSeconds},
                                       std::pair{"transitionSeconds", key.transitionSeconds}}) {
      if (!(std::isfinite(value) && value >= 0.0 && value <= kMaxKeySeconds)) {
        return fail(timeError(i, field, value));
      }
    }
    total += key.holdSeconds + key.transitionSeconds;
  }
  if (repeat && !(total > 0.0)) return fail("a repeating weather schedule must last some time");
  WeatherTimeline timeline;
  timeline.keys_.assign(keys.begin(), keys.end());
  timeline.repeat_ = repeat;
  timeline.measure();
  return timeline;
}

void WeatherTimeline::transitionTo(const WeatherState& target, double atSeconds, double seconds) {
  const WeatherState now = stateAt(atSeconds);
  const glm::dvec2 displacement = windDisplacementAt(atSeconds);
  keys_ = {WeatherKey{now, 0.0, std::clamp(seconds, 0.0, kMaxKeySeconds)},
           WeatherKey{target, 0.0, 0.0}};
  repeat_ = false;
  originSeconds_ = atSeconds;
  originDisplacement_ = displacement;
  measure();
}

void WeatherTimeline::measure() {
  keyStartSeconds_.assign(keys_.size(), 0.0);
  keyStartDisplacement_.assign(keys_.size(), glm::dvec2(0.0));
  double seconds = 0.0;
  glm::dvec2 displacement(0.0);
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    keyStartSeconds_[i] = seconds;
    keyStartDisplacement_[i] = displacement;
    const double length = keys_[i].holdSeconds + keys_[i].transitionSeconds;
    displacement += displacementWithin(Place{i, length, false});
    seconds += length;
  }
  cycleSeconds_ = seconds;
  cycleDisplacement_ = displacement;
}

std::size_t WeatherTimeline::nextKey(std::size_t key) const {
  if (key + 1 < keys_.size()) return key + 1;
  return repeat_ ? 0 : key;
}

WeatherTimeline::Place WeatherTimeline::placeAt(double seconds) const {
  double t = std::max(seconds - originSeconds_, 0.0);
  if (repeat_) t -= std::floor(t / cycleSeconds_) * cycleSeconds_;
  // The key whose span holds t (the last one whose start is not after it).
  const auto after = std::upper_bound(keyStartSeconds_.begin(), keyStartSeconds_.end(), t);
  const std::size_t key =
      static_cast<std::size_t>(std::distance(keyStartSeconds_.begin(), after)) - 1;
  const double within = t - keyStartSeconds_[key];
  const double length = keys_[key].holdSeconds + keys_[key].transitionSeconds;
  const bool ended = !repeat_ && key + 1 == keys_.size();
  return Place{key, ended ? within : std::min(within, length), ended};
}

glm::dvec2 WeatherTimeline::displacementWithin(const Place& place) const {
  const WeatherKey& key = keys_[place.key];
  const glm::dvec2 from = windVelocity(key.state);
  if (place.ended) return from * place.secondsInKey;  // the last state, held for good
  const double held = std::min(place.secondsInKey, key.holdSeconds);
  glm::dvec2 displacement = from * held;
  const double blending = place.secondsInKey - key.holdSeconds;
  if (blending > 0.0 && key.transitionSeconds > 0.0) {
    const glm::dvec2 to = windVelocity(keys_[nextKey(place.key)].state);
    const double u = std::min(blending / key.transitionSeconds, 1.0);
    displacement += key.transitionSeconds * (from * u + (to - from) * easeIntegral(u));
  }
  return displacement;
}

WeatherPhase WeatherTimeline::phaseAt(double seconds) const {
  const Place place = placeAt(seconds);
  const WeatherKey& key = keys_[place.key];
  const double blending = place.secondsInKey - key.holdSeconds;
  if (place.ended || blending <= 0.0 || key.transitionSeconds <= 0.0) {
    return WeatherPhase{place.key, place.key, 0.0f};
  }
  const double u = std::min(blending / key.transitionSeconds, 1.0);
  return WeatherPhase{place.key, nextKey(place.key), static_cast<float>(ease(u))};
}

WeatherState WeatherTimeline::stateAt(double seconds) const {
  const WeatherPhase phase = phaseAt(seconds);
  if (phase.from == phase.to) return keys_[phase.from].state;
  return blendWeather(keys_[phase.from].state, keys_[phase.to].state, phase.blend);
}

glm::dvec2 WeatherTimeline::windDisplacementAt(double seconds) const {
  const double t = seconds - originSeconds_;
  // Before the origin (a change asked for at a later time): the first state's wind.
  if (t < 0.0) return originDisplacement_ + windVelocity(keys_[0].state) * t;
  const Place place = placeAt(seconds);
  const double cycles = repeat_ ? std::floor(t / cycleSeconds_) : 0.0;
  return originDisplacement_ + cycleDisplacement_ * cycles + keyStartDisplacement_[place.key] +
         displacementWithin(place);
}

}  // namespace clouds
