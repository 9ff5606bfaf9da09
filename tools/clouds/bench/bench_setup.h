#pragma once
// What the accuracy-versus-cost benchmark measures: the canonical views (static, each with its
// own cloud look), a short fly-through path, and the configurations (the quality presets and
// one-knob sweeps around High).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "cloud_harness.h"
#include "clouds/clouds.h"

namespace bench {

struct BenchView {
  std::string name;
  clouds::tools::CloudView view;
  clouds::Settings look;  // coverage, type, ...; every configuration renders over this look
};

// Clear sky, scattered cumulus, overcast, sunset, inside a cloud, above the layer.
std::vector<BenchView> canonicalViews();

// The fly-through: from below the base up into the layer at 150 m/s forward and 100 m/s up,
// turning slowly, one pose per frame at 30 frames per second.
struct FlyThrough {
  clouds::Settings look;
  std::uint32_t frames = 48;
  double framesPerSecond = 30.0;
  clouds::tools::CloudView poseAt(std::uint32_t frame) const;
};
FlyThrough flyThrough(std::uint32_t frames);

// A configuration: settings as a function of the view's look. A sweep groups the points of one
// knob (in order, with High as one of them); presets have no sweep.
struct BenchConfig {
  std::string name;   // "High", "light steps 10", ...
  std::string sweep;  // "" for presets, else the knob ("light steps", ...)
  std::string value;  // the knob's value as shown on the plot ("10")
  bool preset = false;
  // High once more (kHighTimedAgain), last in the interleaving: how far apart two timings of
  // the same work land in this run (the targets' "cheaper" must be more than that).
  bool timingRepeat = false;
  clouds::Quality quality = clouds::Quality::High;  // the base of the configuration
  // Applied to settingsFor(quality, look).
  void (*adjust)(clouds::Settings& settings, double value) = nullptr;
  double knob = 0.0;

  clouds::Settings settingsFor(const clouds::Settings& look) const;
};

inline constexpr const char* kHighTimedAgain = "High, timed again";

// The quality presets Low, Medium, High, Ultra as configurations.
std::vector<BenchConfig> presetConfigs();

// Low, Medium, High, Ultra, then the sweeps (view step, light steps, trace scale, update
// interval, temporal reuse, empty-space skipping). The Reference mode is measured apart.
std::vector<BenchConfig> benchConfigs();

// The sweeps as (name, [indices into benchConfigs(), in knob order, High included]).
struct Sweep {
  std::string name;
  std::vector<std::size_t> configs;
};
std::vector<Sweep> sweepsOf(const std::vector<BenchConfig>& configs);
// The same around another preset: `base` is the preset every sweep passes through, at the
// knob values `baseKnobs` (by sweep name).
std::vector<Sweep> sweepsOf(const std::vector<BenchConfig>& configs, clouds::Quality base,
                            const std::map<std::string, double>& baseKnobs);

// A knob's value as the tables and plots show it ("%g").
std::string number(double value);

// Whether `name` is in a --view or --config selection (an empty one selects everything).
bool selected(const std::vector<std::string>& only, const std::string& name);

}  // namespace bench
