#include "scene/weather_description.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"

namespace sample {
namespace {

using engine::JsonReader;
using nlohmann::json;

// A heading in degrees (0 along +x, 90 towards -z, as the layer's wind) as a direction.
glm::vec2 headingDirection(double degrees) {
  const double r = glm::radians(degrees);
  return {float(std::cos(r)), float(-std::sin(r))};
}

clouds::WeatherState builtIn(clouds::WeatherPreset preset, double windDegrees) {
  clouds::WeatherState state = clouds::weatherPreset(preset);
  state.windDirection = headingDirection(windDegrees);
  return state;
}

NamedWeatherState readState(const JsonReader& r, const std::string& name,
                            const clouds::Settings& layer, double layerWindDegrees) {
  NamedWeatherState named{name, clouds::weatherOf(layer), layerWindDegrees};
  clouds::WeatherState& w = named.state;
  if (r.has("like")) {
    clouds::WeatherPreset preset{};
    const std::string like = r.string("like");
    if (!clouds::parseWeatherPreset(like, &preset)) {
      r.fail("like", "a built-in state (sparse, cloudy, overcast, stormy), got \"" + like + "\"");
    }
    w = builtIn(preset, layerWindDegrees);
  }
  w.coverage = float(r.number("coverage", 0.0, 1.0, w.coverage));
  w.cloudType = float(r.number("cloudType", 0.0, 1.0, w.cloudType));
  w.densityMultiplier = float(r.number("densityMultiplier", 0.0, 1e6, w.densityMultiplier));
  w.anvilBias = float(r.number("anvilBias", 0.0, 1.0, w.anvilBias));
  w.detailErosion = float(r.number("detailErosion", 0.0, 1.0, w.detailErosion));
  if (r.has("wind")) {
    const JsonReader wind = r.object("wind");
    if (wind.has("directionDegrees")) {
      named.windDirectionDegrees = wind.number("directionDegrees", -360.0, 360.0);
      w.windDirection = headingDirection(named.windDirectionDegrees);
    }
    w.windSpeedMetresPerSecond =
        float(wind.number("speedMetresPerSecond", 0.0, 500.0, w.windSpeedMetresPerSecond));
    w.skewMetres = float(wind.number("skewMetres", 0.0, 20000.0, w.skewMetres));
    w.windShearDegrees = float(wind.number("shearDegrees", -180.0, 180.0, w.windShearDegrees));
    wind.finish();
  }
  w.lightningStrikesPerMinute =
      float(r.number("lightningStrikesPerMinute", 0.0, 600.0, w.lightningStrikesPerMinute));
  r.finish();
  return named;
}

}  // namespace

clouds::WeatherTimeline WeatherDescription::timeline() const {
  std::string error;
  const std::optional<clouds::WeatherTimeline> t =
      clouds::WeatherTimeline::schedule(schedule, repeat, &error);
  if (!t) throw engine::Error("weather: " + error);
  return *t;
}

bool WeatherDescription::strikes() const {
  return std::any_of(schedule.begin(), schedule.end(), [](const clouds::WeatherKey& key) {
    return key.state.lightningStrikesPerMinute > 0.0f;
  });
}

clouds::WeatherState WeatherDescription::stormiest() const {
  return std::max_element(schedule.begin(), schedule.end(),
                          [](const clouds::WeatherKey& a, const clouds::WeatherKey& b) {
                            return a.state.lightningStrikesPerMinute <
                                   b.state.lightningStrikesPerMinute;
                          })
      ->state;
}

WeatherDescription readWeather(const JsonReader& r, const clouds::Settings& layer,
                               double layerWindDegrees) {
  WeatherDescription d;
  if (r.has("states")) {
    const JsonReader states = r.object("states");
    for (const std::string& name : states.keys()) {
      clouds::WeatherPreset preset{};
      if (clouds::parseWeatherPreset(name, &preset)) {
        states.fail(name, "a built-in state's name: call it something else");
      }
      d.states.push_back(readState(states.object(name), name, layer, layerWindDegrees));
    }
    states.finish();
  }
  const std::vector<JsonReader> keys = r.objects("schedule");
  if (keys.empty()) r.fail("schedule", "at least one state");
  for (const JsonReader& key : keys) {
    const std::string name = key.string("state");
    clouds::WeatherKey k;
    clouds::WeatherPreset preset{};
    const auto own = std::find_if(d.states.begin(), d.states.end(),
                                  [&](const NamedWeatherState& s) { return s.name == name; });
    if (own != d.states.end()) {
      k.state = own->state;
    } else if (clouds::parseWeatherPreset(name, &preset)) {
      k.state = builtIn(preset, layerWindDegrees);
    } else {
      key.fail("state", "unknown state \"" + name +
                            "\": a built-in one (sparse, cloudy, overcast, stormy) or one of "
                            "\"states\"");
    }
    k.holdSeconds = key.number("holdSeconds", 0.0, 1e7, k.holdSeconds);
    k.transitionSeconds = key.number("transitionSeconds", 0.0, 1e7, k.transitionSeconds);
    key.finish();
    d.scheduleStates.push_back(name);
    d.schedule.push_back(k);
  }
  d.repeat = r.boolean("repeat", d.repeat);
  r.finish();
  std::string error;
  if (!clouds::WeatherTimeline::schedule(d.schedule, d.repeat, &error)) {
    r.fail("schedule", error);
  }
  return d;
}

json weatherJson(const WeatherDescription& weather) {
  json states = json::object();
  for (const NamedWeatherState& named : weather.states) {
    const clouds::WeatherState& w = named.state;
    states[named.name] = {{"coverage", double(w.coverage)},
                          {"cloudType", double(w.cloudType)},
                          {"densityMultiplier", double(w.densityMultiplier)},
                          {"anvilBias", double(w.anvilBias)},
                          {"detailErosion", double(w.detailErosion)},
                          {"wind",
                           {{"directionDegrees", named.windDirectionDegrees},
                            {"speedMetresPerSecond", double(w.windSpeedMetresPerSecond)},
                            {"skewMetres", double(w.skewMetres)},
                            {"shearDegrees", double(w.windShearDegrees)}}},
                          {"lightningStrikesPerMinute", double(w.lightningStrikesPerMinute)}};
  }
  json schedule = json::array();
  for (std::size_t i = 0; i < weather.schedule.size(); ++i) {
    schedule.push_back({{"state", weather.scheduleStates[i]},
                        {"holdSeconds", weather.schedule[i].holdSeconds},
                        {"transitionSeconds", weather.schedule[i].transitionSeconds}});
  }
  json j = {{"schedule", schedule}, {"repeat", weather.repeat}};
  if (!weather.states.empty()) j["states"] = states;
  return j;
}

}  // namespace sample
