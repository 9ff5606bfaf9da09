#pragma once
// A scene's changing weather: the "weather" section of a scene file, read and written back.
//
//   "weather": {
//     "states": {"squall": {"like": "stormy", "coverage": 0.7, "wind": {"speedMetresPerSecond":
//     25}}}, "schedule": [{"state": "sparse", "holdSeconds": 60, "transitionSeconds": 20},
//                  {"state": "squall", "holdSeconds": 90, "transitionSeconds": 30}],
//     "repeat": true,
//     "regions": [{"name": "front", "centre": [6000, -9000], "halfSides": [12000, 2000],
//                  "headingDegrees": 30, "radiusMetres": 1000, "blendMetres": 6000,
//                  "schedule": [{"state": "stormy", "holdSeconds": 90, "transitionSeconds": 30},
//                               {"state": "overcast", "holdSeconds": 60}]}]
//   }
//
// A schedule names built-in states (sparse, cloudy, overcast, stormy: clouds/weather.h, blowing
// the way the layer's wind does) or the scene's own, each the layer's look (or "like" a built-in
// state's) with any of coverage, cloudType, densityMultiplier, anvilBias, detailErosion, wind
// {directionDegrees, speedMetresPerSecond, skewMetres} and lightningStrikesPerMinute changed.
// Without a schedule the layer's own look holds (a scene may change only its regions').
// A key of the layer's schedule may name a painted "weatherMap" (PNG, relative to the scene):
// the map blends into the next key's as its state does. Then every key has a map, its own or
// the layer's clouds.weatherMap; a region's keys have none (a region sets a look over the map).
// A region (clouds::WeatherRegion: a rectangle of half sides `halfSides` (m) turned by
// `headingDegrees` as the wind's, grown by `radiusMetres`, eased into the weather around it
// over `blendMetres`) has one "state" or a "schedule" (and "repeat") of its own. A region with
// a "vortex" {eyeRadiusMetres, eyeWallMetres, wallSpeedMetresPerSecond, spiralArms} is a
// superstorm (clouds::WeatherRegion::Vortex; a disc: no halfSides), at most one per scene.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "clouds/weather.h"
#include "engine/core/json_reader.h"

namespace sample {

struct NamedWeatherState {
  std::string name;
  clouds::WeatherState state;
  double windDirectionDegrees = 0.0;  // as the scene gives it, so it is written back the same
};

// States held and blended in turn, by the names the scene gives them.
struct ScheduleDescription {
  std::vector<std::string> states;  // each key's state, as the schedule names it
  std::vector<clouds::WeatherKey> keys;
  bool repeat = true;
  // Each key's painted weather map, as the schedule gives it (empty: the layer's map, or the
  // procedural weather when it has none).
  std::vector<std::optional<std::filesystem::path>> weatherMaps;

  clouds::WeatherTimeline timeline() const;
  // The state that strikes most (where a storm's cells are looked for).
  clouds::WeatherState stormiest() const;
};

struct RegionDescription {
  std::string name;
  clouds::WeatherRegion place;  // its look is its schedule's
  ScheduleDescription schedule;
  bool steady = false;  // one "state", written back as such
};

struct WeatherDescription {
  std::vector<NamedWeatherState> states;  // the scene's own, by name
  ScheduleDescription schedule;           // one key of the layer's look when the scene has none
  bool ownSchedule = true;                // the scene gave the schedule
  std::vector<RegionDescription> regions;

  // Whether any state, the regions' included, strikes lightning (so the scene needs a storm's
  // cells).
  bool strikes() const;
  // The regions under their stormiest states (where a storm's cells are looked for).
  std::vector<clouds::WeatherRegion> stormiestRegions() const;
};

// Reads the section; `layer` is the scene's cloud settings (a state's defaults, the built-in
// states' wind direction), `layerWindDegrees` its wind's heading, `layerMap` its painted map
// and `sceneDir` where the scene's files are. Throws engine::Error naming the file and field on
// a bad section.
WeatherDescription readWeather(const engine::JsonReader& r, const clouds::Settings& layer,
                               double layerWindDegrees,
                               const std::optional<std::filesystem::path>& layerMap,
                               const std::filesystem::path& sceneDir);
// Each key's painted map for the layer's schedule (its own, else `layerMap`), or none when no
// key of the schedule names one.
std::vector<std::filesystem::path> scheduledWeatherMaps(
    const ScheduleDescription& schedule, const std::optional<std::filesystem::path>& layerMap);
nlohmann::json weatherJson(const WeatherDescription& weather);

}  // namespace sample
