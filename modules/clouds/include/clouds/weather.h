#pragma once
// Weather that changes: the look of the sky as one state, built-in states, and a timeline that
// holds states and blends between them (Schneider 2017: weather states lerped over 10-30 s).
// Plain CPU code on FrameInputs::timeSeconds' clock.
//
// Each frame a host applies the timeline's state to its settings and passes where the wind has
// carried the clouds:
//
//   settings = clouds::withWeather(settings, timeline.stateAt(time));
//   inputs.windDisplacementMetres = timeline.windDisplacementAt(time);
//
// The temporal history survives a transition: a state blended over a few seconds or more
// moves each field by less per frame than the history's tolerance (clouds.h, Settings), and
// the wind's displacement is the integral of the blended wind, so the noise never jumps when
// the wind changes (timeSeconds x a new wind would move it by kilometres).
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "clouds/clouds.h"

namespace clouds {

// What makes one weather look like itself: the Settings fields a change of weather moves, and
// the storm's strike rate for a host's lightning (the module strikes nothing itself).
// Ranges as Settings documents them.
struct WeatherState {
  float coverage = 0.5f;                   // Settings::coverage
  float cloudType = 0.75f;                 // Settings::cloudType
  float densityMultiplier = 1.0f;          // Settings::densityMultiplier
  float anvilBias = 0.0f;                  // Settings::anvilBias
  float detailErosion = 0.45f;             // Settings::detailErosion
  glm::vec2 windDirection{1.0f, 0.0f};     // Settings::windDirection
  float windSpeedMetresPerSecond = 10.0f;  // Settings::windSpeedMetresPerSecond
  float skewMetres = 500.0f;               // Settings::skewMetres
  float windShearDegrees = 0.0f;           // Settings::windShearDegrees
  float lightningStrikesPerMinute = 0.0f;  // [0, 600] a storm cell's mean rate; 0: no strikes

  bool operator==(const WeatherState&) const = default;
};

// The built-in states, fairest first.
enum class WeatherPreset : std::uint32_t { Sparse, Cloudy, Overcast, Stormy };
inline constexpr WeatherPreset kWeatherPresets[] = {WeatherPreset::Sparse, WeatherPreset::Cloudy,
                                                    WeatherPreset::Overcast, WeatherPreset::Stormy};
WeatherState weatherPreset(WeatherPreset preset);
const char* weatherPresetName(WeatherPreset preset);  // "sparse", "cloudy", ...
// Parses a weatherPresetName() case-insensitively; false (and *preset untouched) when unknown.
bool parseWeatherPreset(std::string_view name, WeatherPreset* preset);

// The state `settings` hold (no strikes), and `settings` with `state`'s fields.
WeatherState weatherOf(const Settings& settings);
Settings withWeather(Settings settings, const WeatherState& state);

// `region` with `state`'s look (coverage, type, density, anvils: what a region sets).
WeatherRegion withWeather(WeatherRegion region, const WeatherState& state);

// How much a region holds over a world column (x, z metres), [0, 1]: 1 in its core, eased to
// 0 over its blend distance, as the march weighs it.
float weatherRegionStrength(const WeatherRegion& region, glm::dvec2 xzMetres);

// The weather over a world column: `surrounding`, with each region's state (states[i] for
// regions[i]) blended over it in order by its strength there (blendWeather()), as the march
// composes their looks. For a host's own uses of the whole state (a storm's strike rate where
// its cells are); the module renders only the look fields of a region (clouds.h).
WeatherState weatherAt(const WeatherState& surrounding, std::span<const WeatherRegion> regions,
                       std::span<const WeatherState> states, glm::dvec2 xzMetres);

// "" when every field is in range, else "WeatherState.<field> = <value>: <reason>" for the
// first field at fault.
std::string validateWeatherState(const WeatherState& state);

// The wind of a state as a velocity (x, z metres per second).
glm::dvec2 windVelocity(const WeatherState& state);

// From `a` (t = 0) to `b` (t = 1): every field linear in t, the wind as a velocity (so its
// speed dips when the two blow apart, and its direction turns the short way).
WeatherState blendWeather(const WeatherState& a, const WeatherState& b, float t);

// One state of a schedule: held, then blended into the next one.
struct WeatherKey {
  WeatherState state;
  double holdSeconds = 60.0;        // [0, 1e7]: the state as it is
  double transitionSeconds = 20.0;  // [0, 1e7]: then the blend into the next key's state
};

// Where a timeline is at a time: blending from keys[from] to keys[to] (equal while holding).
struct WeatherPhase {
  std::size_t from = 0;
  std::size_t to = 0;
  float blend = 0.0f;  // [0, 1] of the way to `to`, eased (smoothstep)
};

// Weather over time: states held and blended in turn, from time 0 on. A pure function of its
// keys and the time (any time: hours of uptime keep sub-millisecond phases), so reruns and
// thread counts give the same weather.
class WeatherTimeline {
 public:
  // Steady weather.
  explicit WeatherTimeline(const WeatherState& state = {});
  // A schedule: each key's state held for its holdSeconds, then blended into the next key's
  // over its transitionSeconds (eased: smoothstep, so nothing jumps at either end); after the
  // last key, back into the first when `repeat`, else the last state stays. nullopt and `error`
  // filled when there is no key, a key's state or times are out of range, or a repeating
  // schedule lasts no time at all.
  static std::optional<WeatherTimeline> schedule(std::span<const WeatherKey> keys, bool repeat,
                                                 std::string* error);

  // A change asked for during play: from `atSeconds` on, the weather blends from what it is
  // then into `target` over `seconds` (>= 0) and stays there (a schedule's repeat ends). Times
  // before `atSeconds` read the state at `atSeconds`, the wind's displacement stays continuous.
  void transitionTo(const WeatherState& target, double atSeconds, double seconds);

  WeatherState stateAt(double seconds) const;
  // Where the wind has carried the clouds' noise by `seconds` (x, z metres): the integral of
  // the blended wind's velocity from time 0 (FrameInputs::windDisplacementMetres).
  glm::dvec2 windDisplacementAt(double seconds) const;
  WeatherPhase phaseAt(double seconds) const;

  std::span<const WeatherKey> keys() const { return keys_; }
  bool repeats() const { return repeat_; }

 private:
  // The timeline from its origin on: keys_ in turn, key 0 beginning at the origin.
  struct Place {
    std::size_t key = 0;
    double secondsInKey = 0.0;  // [0, hold + transition)
    bool ended = false;         // past a non-repeating schedule's last key
  };
  Place placeAt(double seconds) const;
  std::size_t nextKey(std::size_t key) const;
  // The wind's displacement from the start of place.key to the place.
  glm::dvec2 displacementWithin(const Place& place) const;
  void measure();  // keyStart*_ and cycle*_ from keys_

  std::vector<WeatherKey> keys_;
  std::vector<double> keyStartSeconds_;           // where each key begins after the origin
  std::vector<glm::dvec2> keyStartDisplacement_;  //   and the wind's displacement there
  bool repeat_ = false;
  double originSeconds_ = 0.0;
  glm::dvec2 originDisplacement_{0.0};
  // Of one pass through keys_: its length (s) and the wind's displacement over it.
  double cycleSeconds_ = 0.0;
  glm::dvec2 cycleDisplacement_{0.0};
};

}  // namespace clouds
