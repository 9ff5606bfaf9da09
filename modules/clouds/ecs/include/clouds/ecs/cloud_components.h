#pragma once
// The clouds as ECS data. A scene with a CloudLayer entity gets the clouds module (its systems,
// pipelines and passes); a scene without one gets none of it.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clouds/clouds.h"
#include "clouds/hero_cloud_life.h"
#include "clouds/nvdf.h"
#include "clouds/weather.h"

namespace clouds::ecs {

struct CloudLayer {
  clouds::Settings settings;
  std::uint32_t noiseSeed = 1;
  std::optional<std::filesystem::path> weatherMap;  // painted weather (PNG), else procedural
  // The hero clouds' assets, read and validated when the scene loaded. Entities with a
  // clouds::HeroCloud component place them (its `asset` indexes this list), and a
  // clouds::HeroCloudLifecycle beside it makes one come and go; each frame draws the
  // kMaxHeroClouds nearest the camera. None: the module loads no atlas and runs no hero march.
  std::vector<std::shared_ptr<const clouds::NvdfVolume>> heroCloudAssets;
};

// A place on the map with weather of its own (clouds::WeatherRegion), on a timeline of its own:
// a storm front over the range that builds and clears while the plains stay fair.
struct RegionalWeather {
  std::string name;             // for HUDs and logs
  clouds::WeatherRegion place;  // where; its look is the timeline's state's at the clock
  clouds::WeatherTimeline timeline;
  std::vector<std::string> keyNames;  // what each of its timeline's keys is called
};

// Beside a CloudLayer: weather that changes on FrameTime's clock (clouds/weather.h). Each
// frame the layer renders the timeline's state over its settings (coverage, type, density,
// anvils, erosion, wind and skew), its regions' states over the places they hold, the clouds
// drift as far as the timeline's wind has carried them, and a LightningStorm's cells strike at
// the rate of the weather over each. Without one the weather is the layer's settings.
struct CloudWeather {
  clouds::WeatherTimeline timeline;
  std::vector<std::string> keyNames;     // what each of its keys is called, for HUDs and logs
  std::vector<RegionalWeather> regions;  // at most clouds::kMaxWeatherRegions, applied in order
  // Painted weather on the timeline: each key's map (PNG: R coverage, G type, B density), one
  // per key, read when the clouds module installs. Each frame the module renders the map of
  // the key the timeline holds, blended into the next key's as the state is
  // (FrameInputs::weatherBlendView), so the history survives the change. Empty: the layer's
  // weatherMap (or the procedural weather) throughout.
  std::vector<std::filesystem::path> keyWeatherMaps;

  // The weather over a world column (x, z metres) at `seconds`: the timeline's with the
  // regions' blended over it (clouds::weatherAt()).
  clouds::WeatherState stateAt(double seconds, glm::dvec2 xzMetres) const;
  // The regions at `seconds`, each with its timeline's look (FrameInputs::weatherRegions).
  std::vector<clouds::WeatherRegion> regionsAt(double seconds) const;
};

// A preset's march precision knobs tuned by hand (a player's panel, an engine's own tuning):
// each one set replaces the preset's value. They are the knobs that select no pipeline and
// keep the temporal history (setting_effects: the march's precision), so a change shows at the
// next frame without a hitch. Ranges as clouds::Settings documents them.
struct CloudQualityKnobs {
  std::optional<std::uint32_t> maxViewSteps;  // view samples a ray at most
  std::optional<float> viewStepMetres;        // the first view step, metres
  std::optional<std::uint32_t> lightSteps;    // samples towards the sun per view sample
  std::optional<float> transmittanceCutoff;   // a ray stops below this transmittance

  bool any() const { return maxViewSteps || viewStepMetres || lightSteps || transmittanceCutoff; }
  // `settings` with the knobs that are set.
  clouds::Settings appliedTo(clouds::Settings settings) const;
  bool operator==(const CloudQualityKnobs&) const = default;
};

// On a camera entity: the quality preset its clouds render with, settingsFor(preset) over the
// layer's look, with its knobs tuned. A camera without one renders the layer's settings as
// they are.
struct CloudQuality {
  clouds::Quality preset = clouds::Quality::Medium;
  CloudQualityKnobs knobs;  // none set: the preset as it is
};

// Context singleton the clouds module keeps up to date, for HUDs and logs: how the clouds
// rendered (the module's report of its last frame, the pass times of the latest completed
// frame, its GPU memory) and the last error, if any. Read-only for everyone else.
struct CloudStatus {
  clouds::FrameReport report;
  std::vector<clouds::PassTiming> passTimings;
  clouds::MemoryUsage memory;
  std::string lastError;  // empty when the last frame rendered
};

}  // namespace clouds::ecs
