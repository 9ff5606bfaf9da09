#pragma once
// A scene's changing weather: the "weather" section of a scene file, read and written back.
//
//   "weather": {
//     "states": {"squall": {"like": "stormy", "coverage": 0.7, "wind": {"speedMetresPerSecond":
//     25}}}, "schedule": [{"state": "sparse", "holdSeconds": 60, "transitionSeconds": 20},
//                  {"state": "squall", "holdSeconds": 90, "transitionSeconds": 30}],
//     "repeat": true
//   }
//
// A schedule names built-in states (sparse, cloudy, overcast, stormy: clouds/weather.h, blowing
// the way the layer's wind does) or the scene's own, each the layer's look (or "like" a built-in
// state's) with any of coverage, cloudType, densityMultiplier, anvilBias, detailErosion, wind
// {directionDegrees, speedMetresPerSecond, skewMetres} and lightningStrikesPerMinute changed.
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

struct WeatherDescription {
  std::vector<NamedWeatherState> states;    // the scene's own, by name
  std::vector<std::string> scheduleStates;  // each key's state, as the schedule names it
  std::vector<clouds::WeatherKey> schedule;
  bool repeat = true;

  clouds::WeatherTimeline timeline() const;
  // Whether any state of the schedule strikes lightning (so the scene needs a storm's cells).
  bool strikes() const;
  // The schedule's state that strikes most (where a storm's cells are looked for).
  clouds::WeatherState stormiest() const;
};

// Reads the section; `layer` is the scene's cloud settings (a state's defaults, the built-in
// states' wind direction) and `layerWindDegrees` its wind's heading. Throws engine::Error naming
// the file and field on a bad section.
WeatherDescription readWeather(const engine::JsonReader& r, const clouds::Settings& layer,
                               double layerWindDegrees);
nlohmann::json weatherJson(const WeatherDescription& weather);

}  // namespace sample
