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
// A region (clouds::WeatherRegion: a rectangle of half sides `halfSides` (m) turned by
// `headingDegrees` as the wind's, grown by `radiusMetres`, eased into the weather around it
// over `blendMetres`) has one "state" or a "schedule" (and "repeat") of its own. A region with
// a "vortex" {eyeRadiusMetres, eyeWallMetres, wallSpeedMetresPerSecond, spiralArms} is a
// superstorm (clouds::WeatherRegion::Vortex; a disc: no halfSides), at most one per scene.
#include <nlohmann/json.hpp>
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
// states' wind direction) and `layerWindDegrees` its wind's heading. Throws engine::Error naming
// the file and field on a bad section.
WeatherDescription readWeather(const engine::JsonReader& r, const clouds::Settings& layer,
                               double layerWindDegrees);
nlohmann::json weatherJson(const WeatherDescription& weather);

}  // namespace sample
