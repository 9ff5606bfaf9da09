#include "game/live_settings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "clouds/ecs/lightning.h"
#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/render/exposure.h"
#include "engine/render/scene_components.h"
#include "game/game_components.h"
#include "scene/scene_writer.h"

namespace sample {
namespace {

using engine::ecs::World;

bool hasClouds(const LiveScene& live) {
  return live.scene.clouds.has_value();
}
bool always(const LiveScene&) {
  return true;
}
bool loadedWithGodRays(const LiveScene& live) {
  return live.scene.clouds && live.loaded.clouds && live.loaded.clouds->settings.godRaySamples > 0;
}
bool loadedWithShadows(const LiveScene& live) {
  return live.scene.clouds && live.loaded.clouds && live.loaded.clouds->settings.shadowCascades > 0;
}
bool loadedWithLightning(const LiveScene& live) {
  return live.scene.lightning && live.loaded.lightning;
}

// God rays on or off: the layer's samples (a preset picks its own count while on). Only in a
// scene loaded with them, whose pipelines include the frames without (the sun off screen).
void setGodRays(World& world, SceneDescription& s, double on) {
  const std::uint32_t samples = on >= 0.5 ? kSceneGodRaySamples : 0u;
  s.clouds->settings.godRaySamples = samples;
  world.view<clouds::ecs::CloudLayer>().each(
      [&](clouds::ecs::CloudLayer& layer) { layer.settings.godRaySamples = samples; });
}

// The clouds' shadow map on or off: its cascades as loaded, or none. Off, the module drops the
// map and its pass, and the terrain's sunlight map is made lit (terrain_sunlight.h); back on,
// the map is made again over the next frames (its memory allocated again).
void setShadows(World& world, SceneDescription& s, double on) {
  const std::uint32_t cascades =
      on >= 0.5 ? world.ctx().get<LiveScene>().loaded.clouds->settings.shadowCascades : 0u;
  s.clouds->settings.shadowCascades = cascades;
  world.view<clouds::ecs::CloudLayer>().each(
      [&](clouds::ecs::CloudLayer& layer) { layer.settings.shadowCascades = cascades; });
}

// The storm's strike rate; 0 turns lightning off (strikes under way fade out as they would).
void setStrikesPerMinute(World& world, SceneDescription& s, double rate) {
  s.lightning->storm.strikesPerMinute = rate;
  world.view<clouds::ecs::LightningStorm>().each(
      [&](clouds::ecs::LightningStorm& storm) { storm.strikesPerMinute = rate; });
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

// A march precision knob of the camera's cloud preset (CloudQualityKnobs): shows the preset's
// value until set; setting it fixes the preset (a governor's rungs are the presets as they
// are), the world's camera and the scene alike.
template <typename T, std::optional<T> clouds::ecs::CloudQualityKnobs::*Knob,
          T clouds::Settings::*Field>
LiveSetting cloudKnob(const char* name, const char* label, double min, double max) {
  return LiveSetting{
      name,
      label,
      min,
      max,
      hasClouds,
      [](const SceneDescription& s) {
        const std::optional<T>& knob = s.camera.cloudKnobs.*Knob;
        return double(knob ? *knob : clouds::settingsFor(s.camera.cloudQuality).*Field);
      },
      [](World& world, SceneDescription& s, double value) {
        const T v = std::is_integral_v<T> ? T(std::lround(value)) : T(value);
        world.view<clouds::ecs::CloudQuality>().each(
            [&](engine::ecs::Entity camera, clouds::ecs::CloudQuality& quality) {
              quality.knobs.*Knob = v;
              world.remove<clouds::ecs::CloudFrameBudget>(camera);
              s.camera.cloudQuality = quality.preset;
            });
        s.camera.cloudKnobs.*Knob = v;
        s.camera.frameTargetMilliseconds = 0.0;
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

const std::array<LiveSetting, 22>& table() {
  using S = clouds::Settings;
  using K = clouds::ecs::CloudQualityKnobs;
  static const std::array<LiveSetting, 22> kSettings = {
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
      cloudSetting<&S::windShearDegrees>("clouds.wind.shearDegrees", "shear (deg)", -180.0, 180.0),
      cloudSetting<&S::sunStrength>("clouds.lighting.sunStrength", "sunlight", 0.0, 5.0),
      cloudSetting<&S::ambientStrength>("clouds.lighting.ambientStrength", "sky light", 0.0, 5.0),
      cloudSetting<&S::silverIntensity>("clouds.lighting.silverIntensity", "silver lining", 0.0,
                                        5.0),
      LiveSetting{"clouds.godRays", "god rays", 0.0, 1.0, loadedWithGodRays,
                  [](const SceneDescription& s) {
                    return s.clouds->settings.godRaySamples > 0 ? 1.0 : 0.0;
                  },
                  setGodRays, true},
      LiveSetting{"clouds.shadows", "cloud shadows", 0.0, 1.0, loadedWithShadows,
                  [](const SceneDescription& s) {
                    return s.clouds->settings.shadowCascades > 0 ? 1.0 : 0.0;
                  },
                  setShadows, true},
      LiveSetting{"lightning.strikesPerMinute", "strikes/min (0: off)", 0.0, 60.0,
                  loadedWithLightning,
                  [](const SceneDescription& s) { return s.lightning->storm.strikesPerMinute; },
                  setStrikesPerMinute},
      LiveSetting{"sun.timeOfDayHours", "time of day (h)", 0.0, 23.99, always,
                  [](const SceneDescription& s) { return s.sun.timeOfDayHours; }, setTimeOfDay},
      LiveSetting{"sun.hoursPerSecond", "clock (h/s)", 0.0, 1.0, always,
                  [](const SceneDescription& s) { return s.sun.hoursPerSecond; },
                  setHoursPerSecond},
      LiveSetting{"exposure.compensationEv", "exposure (EV)", -5.0, 5.0, always,
                  [](const SceneDescription& s) { return s.exposure.compensationEv; },
                  setCompensation},
      cloudKnob<std::uint32_t, &K::maxViewSteps, &S::maxViewSteps>("camera.cloudKnobs.maxViewSteps",
                                                                   "view samples", 8.0, 512.0),
      cloudKnob<float, &K::viewStepMetres, &S::viewStepMetres>("camera.cloudKnobs.viewStepMetres",
                                                               "view step (m)", 5.0, 300.0),
      cloudKnob<std::uint32_t, &K::lightSteps, &S::lightSteps>("camera.cloudKnobs.lightSteps",
                                                               "light samples", 0.0, 24.0),
      cloudKnob<float, &K::transmittanceCutoff, &S::transmittanceCutoff>(
          "camera.cloudKnobs.transmittanceCutoff", "ray cutoff", 0.0, 0.05),
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
  if (!setting->available(live)) {
    throw engine::Error("set: " + std::string(name) + ": the scene has nothing it tunes");
  }
  if (!(value >= setting->min && value <= setting->max)) {
    throw engine::Error("set: " + std::string(name) + ": must be in [" +
                        std::to_string(setting->min) + ", " + std::to_string(setting->max) +
                        "], got " + std::to_string(value));
  }
  setting->set(world, live.scene, value);
}

void syncLiveScene(World& world) {
  SceneDescription& scene = world.ctx().get<LiveScene>().scene;
  world.view<const TimeOfDay>().each(
      [&](const TimeOfDay& t) { scene.sun.timeOfDayHours = t.hours; });
  world.view<const clouds::ecs::CloudQuality>().each(
      [&](engine::ecs::Entity camera, const clouds::ecs::CloudQuality& quality) {
        scene.camera.cloudQuality = quality.preset;
        scene.camera.cloudKnobs = quality.knobs;
        const auto* budget = world.tryGet<const clouds::ecs::CloudFrameBudget>(camera);
        scene.camera.frameTargetMilliseconds = budget != nullptr ? budget->targetMilliseconds : 0.0;
      });
}

SceneDescription sceneToSave(World& world, SavedStart start) {
  syncLiveScene(world);
  SceneDescription scene = world.ctx().get<LiveScene>().scene;
  if (start == SavedStart::Here) {
    world.view<const engine::render::Camera, const Aircraft>().each(
        [&](const engine::render::Camera& camera, const Aircraft& aircraft) {
          // The inverse of the scene's start (yaw about +y, then pitch; 0 looks along -z).
          // engine::render::forwardOf()'s, without its library (the fuzzed readers link this).
          const glm::dvec3 forward = camera.orientation * glm::dvec3(0.0, 0.0, -1.0);
          scene.camera.position = camera.position;
          scene.camera.yawDegrees = glm::degrees(std::atan2(-forward.x, -forward.z));
          // A scene starts within 89 degrees of level (straight up or down has no heading).
          scene.camera.pitchDegrees =
              std::clamp(glm::degrees(std::asin(std::clamp(forward.y, -1.0, 1.0))), -89.0, 89.0);
          scene.camera.speedMetresPerSecond = aircraft.speedMetresPerSecond;
        });
  }
  return scene;
}

bool saveLiveScene(World& world, SavedStart start) {
  auto& live = world.ctx().get<LiveScene>();
  try {
    writeSceneFile(sceneToSave(world, start), live.saveTo);
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
