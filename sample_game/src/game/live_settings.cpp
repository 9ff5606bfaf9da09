#include "game/live_settings.h"

#include <array>
#include <cmath>
#include <string>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/render/exposure.h"
#include "game/game_components.h"
#include "scene/scene_writer.h"

namespace sample {
namespace {

using engine::ecs::World;

bool hasClouds(const SceneDescription& s) {
  return s.clouds.has_value();
}
bool always(const SceneDescription&) {
  return true;
}

// A field of the cloud layer's settings, in the world's CloudLayer and the scene alike.
template <float clouds::Settings::*Field>
LiveSetting cloudSetting(const char* name, const char* label, double min, double max) {
  return LiveSetting{
      name,
      label,
      min,
      max,
      hasClouds,
      [](const SceneDescription& s) { return double(s.clouds->settings.*Field); },
      [](World& world, SceneDescription& s, double value) {
        s.clouds->settings.*Field = float(value);
        world.view<clouds::ecs::CloudLayer>().each(
            [&](clouds::ecs::CloudLayer& layer) { layer.settings.*Field = float(value); });
      }};
}

void setWindDirection(World& world, SceneDescription& s, double degrees) {
  // As the scene reader makes it, so that a saved scene's wind is the same to the bit.
  s.clouds->windDirectionDegrees = degrees;
  const double radians = glm::radians(degrees);
  const glm::vec2 direction(float(std::cos(radians)), float(-std::sin(radians)));
  s.clouds->settings.windDirection = direction;
  world.view<clouds::ecs::CloudLayer>().each(
      [&](clouds::ecs::CloudLayer& layer) { layer.settings.windDirection = direction; });
}

void setTimeOfDay(World& world, SceneDescription& s, double hours) {
  s.sun.timeOfDayHours = hours;
  world.view<TimeOfDay>().each([&](TimeOfDay& t) { t.hours = hours; });
}

void setHoursPerSecond(World& world, SceneDescription& s, double rate) {
  s.sun.hoursPerSecond = rate;
  world.view<TimeOfDay>().each([&](TimeOfDay& t) { t.hoursPerSecond = rate; });
}

void setCompensation(World& world, SceneDescription& s, double ev) {
  s.exposure.compensationEv = ev;
  world.ctx().get<engine::render::Exposure>().compensationEv = float(ev);
}

const std::array<LiveSetting, 14>& table() {
  using S = clouds::Settings;
  static const std::array<LiveSetting, 14> kSettings = {
      cloudSetting<&S::coverage>("clouds.coverage", "coverage", 0.0, 1.0),
      cloudSetting<&S::cloudType>("clouds.cloudType", "cloud type", 0.0, 1.0),
      cloudSetting<&S::densityMultiplier>("clouds.densityMultiplier", "density", 0.0, 5.0),
      cloudSetting<&S::anvilBias>("clouds.anvilBias", "anvil bias", 0.0, 1.0),
      cloudSetting<&S::detailErosion>("clouds.detailErosion", "detail erosion", 0.0, 1.0),
      cloudSetting<&S::windSpeedMetresPerSecond>("clouds.wind.speedMetresPerSecond", "wind (m/s)",
                                                 0.0, 100.0),
      LiveSetting{"clouds.wind.directionDegrees", "wind from (deg)", -180.0, 180.0, hasClouds,
                  [](const SceneDescription& s) { return s.clouds->windDirectionDegrees; },
                  setWindDirection},
      cloudSetting<&S::skewMetres>("clouds.wind.skewMetres", "skew (m)", 0.0, 5000.0),
      cloudSetting<&S::sunStrength>("clouds.lighting.sunStrength", "sunlight", 0.0, 5.0),
      cloudSetting<&S::ambientStrength>("clouds.lighting.ambientStrength", "sky light", 0.0, 5.0),
      cloudSetting<&S::silverIntensity>("clouds.lighting.silverIntensity", "silver lining", 0.0,
                                        5.0),
      LiveSetting{"sun.timeOfDayHours", "time of day (h)", 0.0, 23.99, always,
                  [](const SceneDescription& s) { return s.sun.timeOfDayHours; }, setTimeOfDay},
      LiveSetting{"sun.hoursPerSecond", "clock (h/s)", 0.0, 1.0, always,
                  [](const SceneDescription& s) { return s.sun.hoursPerSecond; },
                  setHoursPerSecond},
      LiveSetting{"exposure.compensationEv", "exposure (EV)", -5.0, 5.0, always,
                  [](const SceneDescription& s) { return s.exposure.compensationEv; },
                  setCompensation},
  };
  return kSettings;
}

}  // namespace

std::span<const LiveSetting> liveSettings() {
  return table();
}

const LiveSetting* findLiveSetting(std::string_view name) {
  for (const LiveSetting& setting : table()) {
    if (name == setting.name) return &setting;
  }
  return nullptr;
}

void applyLiveSetting(World& world, std::string_view name, double value) {
  const LiveSetting* setting = findLiveSetting(name);
  if (setting == nullptr) throw engine::Error("set: no live setting \"" + std::string(name) + "\"");
  auto& live = world.ctx().get<LiveScene>();
  if (!setting->available(live.scene)) {
    throw engine::Error("set: " + std::string(name) + ": the scene has nothing it tunes");
  }
  if (!(value >= setting->min && value <= setting->max)) {
    throw engine::Error("set: " + std::string(name) + ": must be in [" +
                        std::to_string(setting->min) + ", " + std::to_string(setting->max) +
                        "], got " + std::to_string(value));
  }
  setting->set(world, live.scene, value);
}

SceneDescription sceneToSave(World& world) {
  SceneDescription scene = world.ctx().get<LiveScene>().scene;
  world.view<const TimeOfDay>().each(
      [&](const TimeOfDay& t) { scene.sun.timeOfDayHours = t.hours; });
  world.view<const clouds::ecs::CloudQuality>().each(
      [&](engine::ecs::Entity camera, const clouds::ecs::CloudQuality& quality) {
        scene.camera.cloudQuality = quality.preset;
        const auto* budget = world.tryGet<const clouds::ecs::CloudFrameBudget>(camera);
        scene.camera.frameTargetMilliseconds = budget != nullptr ? budget->targetMilliseconds : 0.0;
      });
  return scene;
}

bool saveLiveScene(World& world) {
  auto& live = world.ctx().get<LiveScene>();
  try {
    writeSceneFile(sceneToSave(world), live.saveTo);
    live.lastSave = "saved " + live.saveTo.string();
    engine::log::info(live.lastSave);
    return true;
  } catch (const engine::Error& error) {
    live.lastSave = error.what();
    engine::log::error(live.lastSave);
    return false;
  }
}

}  // namespace sample
