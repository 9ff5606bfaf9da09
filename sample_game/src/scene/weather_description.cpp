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

// The state a key or region names: one of the scene's `states`, or a built-in one.
clouds::WeatherState namedState(const JsonReader& r, const char* field, const std::string& name,
                                const std::vector<NamedWeatherState>& states,
                                double layerWindDegrees) {
  const auto own = std::find_if(states.begin(), states.end(),
                                [&](const NamedWeatherState& s) { return s.name == name; });
  if (own != states.end()) return own->state;
  clouds::WeatherPreset preset{};
  if (!clouds::parseWeatherPreset(name, &preset)) {
    r.fail(field, "unknown state \"" + name +
                      "\": a built-in one (sparse, cloudy, overcast, stormy) or one of "
                      "\"states\"");
  }
  return builtIn(preset, layerWindDegrees);
}

// The keys of a "schedule" in `r` (and its "repeat"), each naming a built-in state or one of
// `states`, and (with a `sceneDir`: the layer's schedule) a painted map.
ScheduleDescription readSchedule(const JsonReader& r, const std::vector<NamedWeatherState>& states,
                                 double layerWindDegrees,
                                 const std::filesystem::path* sceneDir = nullptr) {
  ScheduleDescription d;
  const std::vector<JsonReader> keys = r.objects("schedule");
  if (keys.empty()) r.fail("schedule", "at least one state");
  for (const JsonReader& key : keys) {
    const std::string name = key.string("state");
    clouds::WeatherKey k;
    k.state = namedState(key, "state", name, states, layerWindDegrees);
    k.holdSeconds = key.number("holdSeconds", 0.0, 1e7, k.holdSeconds);
    k.transitionSeconds = key.number("transitionSeconds", 0.0, 1e7, k.transitionSeconds);
    if (key.has("weatherMap") && sceneDir == nullptr) {
      key.fail("weatherMap",
               "a region sets a look over the layer's map: only the layer's "
               "schedule paints maps");
    }
    d.weatherMaps.push_back(key.has("weatherMap")
                                ? std::optional(key.existingFile("weatherMap", *sceneDir))
                                : std::nullopt);
    key.finish();
    d.states.push_back(name);
    d.keys.push_back(k);
  }
  d.repeat = r.boolean("repeat", d.repeat);
  std::string error;
  if (!clouds::WeatherTimeline::schedule(d.keys, d.repeat, &error)) r.fail("schedule", error);
  return d;
}

RegionDescription readRegion(const JsonReader& r, const std::vector<NamedWeatherState>& states,
                             double layerWindDegrees) {
  RegionDescription d;
  d.name = r.string("name");
  clouds::WeatherRegion& p = d.place;
  const glm::dvec2 centre = r.vec2("centre", -1e7, 1e7);
  p.centreMetres = centre;
  if (r.has("halfSides")) p.halfSidesMetres = glm::vec2(r.vec2("halfSides", 0.0, 1e7));
  p.headingDegrees = float(r.number("headingDegrees", -360.0, 360.0, p.headingDegrees));
  p.radiusMetres = float(r.number("radiusMetres", 0.0, 1e7, p.radiusMetres));
  p.blendMetres = float(r.number("blendMetres", 100.0, 1e7, p.blendMetres));
  if (r.has("vortex")) {
    const JsonReader v = r.object("vortex");
    clouds::WeatherRegion::Vortex& vortex = p.vortex;
    vortex.eyeRadiusMetres = float(v.number("eyeRadiusMetres", 1.0, 1e6));
    vortex.eyeWallMetres = float(v.number("eyeWallMetres", 100.0, 1e6, vortex.eyeWallMetres));
    vortex.wallSpeedMetresPerSecond =
        float(v.number("wallSpeedMetresPerSecond", -200.0, 200.0, vortex.wallSpeedMetresPerSecond));
    vortex.spiralArms = float(v.number("spiralArms", 0.0, 8.0, vortex.spiralArms));
    v.finish();
    if (p.halfSidesMetres != glm::vec2(0.0f)) {
      r.fail("halfSides", "a superstorm's region is a disc: no halfSides with a vortex");
    }
  }
  if (r.has("state") == r.has("schedule")) {
    r.fail("state", "a region needs either a state or a schedule");
  }
  if (r.has("state")) {
    const std::string name = r.string("state");
    d.schedule.states = {name};
    d.schedule.keys = {
        clouds::WeatherKey{namedState(r, "state", name, states, layerWindDegrees), 60.0, 0.0}};
    d.schedule.repeat = false;
    d.steady = true;
  } else {
    d.schedule = readSchedule(r, states, layerWindDegrees);
  }
  r.finish();
  return d;
}

}  // namespace

clouds::WeatherTimeline ScheduleDescription::timeline() const {
  std::string error;
  const std::optional<clouds::WeatherTimeline> t =
      clouds::WeatherTimeline::schedule(keys, repeat, &error);
  if (!t) throw engine::Error("weather: " + error);
  return *t;
}

clouds::WeatherState ScheduleDescription::stormiest() const {
  return std::max_element(keys.begin(), keys.end(),
                          [](const clouds::WeatherKey& a, const clouds::WeatherKey& b) {
                            return a.state.lightningStrikesPerMinute <
                                   b.state.lightningStrikesPerMinute;
                          })
      ->state;
}

bool WeatherDescription::strikes() const {
  const auto strikes = [](const ScheduleDescription& s) {
    return s.stormiest().lightningStrikesPerMinute > 0.0f;
  };
  return strikes(schedule) ||
         std::any_of(regions.begin(), regions.end(),
                     [&](const RegionDescription& r) { return strikes(r.schedule); });
}

std::vector<clouds::WeatherRegion> WeatherDescription::stormiestRegions() const {
  std::vector<clouds::WeatherRegion> places;
  for (const RegionDescription& r : regions) {
    places.push_back(clouds::withWeather(r.place, r.schedule.stormiest()));
  }
  return places;
}

WeatherDescription readWeather(const JsonReader& r, const clouds::Settings& layer,
                               double layerWindDegrees,
                               const std::optional<std::filesystem::path>& layerMap,
                               const std::filesystem::path& sceneDir) {
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
  if (r.has("regions")) {
    const std::vector<JsonReader> regions = r.objects("regions");
    if (regions.empty()) r.fail("regions", "at least one region, or no \"regions\"");
    if (regions.size() > clouds::kMaxWeatherRegions) {
      r.fail("regions", "at most " + std::to_string(clouds::kMaxWeatherRegions) + " regions");
    }
    for (const JsonReader& region : regions) {
      d.regions.push_back(readRegion(region, d.states, layerWindDegrees));
    }
    const auto storm = [](const RegionDescription& region) {
      return region.place.vortex.eyeRadiusMetres > 0.0f;
    };
    if (std::count_if(d.regions.begin(), d.regions.end(), storm) > 1) {
      r.fail("regions", "at most one superstorm (a region with a vortex)");
    }
  }
  d.ownSchedule = r.has("schedule") || d.regions.empty();
  if (d.ownSchedule) {
    d.schedule = readSchedule(r, d.states, layerWindDegrees, &sceneDir);
    const std::vector<std::optional<std::filesystem::path>>& maps = d.schedule.weatherMaps;
    const bool painted = std::any_of(maps.begin(), maps.end(), [](const auto& m) { return m; });
    for (std::size_t i = 0; painted && !layerMap && i < maps.size(); ++i) {
      if (!maps[i]) {
        r.fail("schedule", "key " + std::to_string(i) + " (\"" + d.schedule.states[i] +
                               "\") has no weatherMap and the layer none: with painted maps "
                               "every key needs one, its own or clouds.weatherMap");
      }
    }
  } else {
    d.schedule.keys = {clouds::WeatherKey{clouds::weatherOf(layer), 60.0, 0.0}};
    d.schedule.states = {"the layer's"};
    d.schedule.weatherMaps = {std::nullopt};
    d.schedule.repeat = false;
    if (r.has("repeat")) r.fail("repeat", "a schedule's: there is none");
  }
  r.finish();
  return d;
}

std::vector<std::filesystem::path> scheduledWeatherMaps(
    const ScheduleDescription& schedule, const std::optional<std::filesystem::path>& layerMap) {
  const auto& own = schedule.weatherMaps;
  if (std::none_of(own.begin(), own.end(), [](const auto& m) { return m.has_value(); })) {
    return {};
  }
  std::vector<std::filesystem::path> maps;
  for (const auto& map : own) maps.push_back(map ? *map : layerMap.value());
  return maps;
}

namespace {

void addSchedule(json& j, const ScheduleDescription& s) {
  json keys = json::array();
  for (std::size_t i = 0; i < s.keys.size(); ++i) {
    keys.push_back({{"state", s.states[i]},
                    {"holdSeconds", s.keys[i].holdSeconds},
                    {"transitionSeconds", s.keys[i].transitionSeconds}});
    if (i < s.weatherMaps.size() && s.weatherMaps[i]) {
      keys.back()["weatherMap"] =
          std::filesystem::absolute(*s.weatherMaps[i]).lexically_normal().string();
    }
  }
  j["schedule"] = keys;
  j["repeat"] = s.repeat;
}

}  // namespace

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
  json j = json::object();
  if (weather.ownSchedule) addSchedule(j, weather.schedule);
  if (!weather.states.empty()) j["states"] = states;
  if (!weather.regions.empty()) {
    json regions = json::array();
    for (const RegionDescription& r : weather.regions) {
      const clouds::WeatherRegion& p = r.place;
      json region = {{"name", r.name},
                     {"centre", {p.centreMetres.x, p.centreMetres.y}},
                     {"halfSides", {double(p.halfSidesMetres.x), double(p.halfSidesMetres.y)}},
                     {"headingDegrees", double(p.headingDegrees)},
                     {"radiusMetres", double(p.radiusMetres)},
                     {"blendMetres", double(p.blendMetres)}};
      if (p.vortex.eyeRadiusMetres > 0.0f) {
        const clouds::WeatherRegion::Vortex& v = p.vortex;
        region["vortex"] = {{"eyeRadiusMetres", double(v.eyeRadiusMetres)},
                            {"eyeWallMetres", double(v.eyeWallMetres)},
                            {"wallSpeedMetresPerSecond", double(v.wallSpeedMetresPerSecond)},
                            {"spiralArms", double(v.spiralArms)}};
      }
      if (r.steady) {
        region["state"] = r.schedule.states.front();
      } else {
        addSchedule(region, r.schedule);
      }
      regions.push_back(region);
    }
    j["regions"] = regions;
  }
  return j;
}

}  // namespace sample
