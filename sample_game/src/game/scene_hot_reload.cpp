#include "game/scene_hot_reload.h"

#include <system_error>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/render/exposure.h"
#include "engine/render/scene_components.h"
#include "game/cloud_quality_controls.h"
#include "game/game_components.h"
#include "game/live_settings.h"
#include "game/water.h"
#include "scene/scene_writer.h"

namespace sample {
namespace {

using engine::ecs::World;

// The scene's cloud layer alone, as written: two layers that write alike are alike.
std::string cloudsText(const std::optional<CloudDescription>& clouds) {
  SceneDescription only;
  only.clouds = clouds;
  return sceneJson(only);
}

std::string heroCloudsText(const std::optional<CloudDescription>& clouds) {
  if (!clouds) return {};
  SceneDescription only;
  only.clouds = CloudDescription{};
  only.clouds->heroClouds = clouds->heroClouds;
  return sceneJson(only);
}

// Whether the cloud layers differ in what only a restart changes: the passes and assets they
// make (shadows, god rays, the painted map, hero clouds) and the noise they are made from.
bool cloudsNeedRestart(const std::optional<CloudDescription>& a,
                       const std::optional<CloudDescription>& b) {
  if (a.has_value() != b.has_value()) return true;
  if (!a) return false;
  return (a->settings.shadowCascades > 0) != (b->settings.shadowCascades > 0) ||
         (a->settings.godRaySamples > 0) != (b->settings.godRaySamples > 0) ||
         a->weatherMap != b->weatherMap || a->noiseSeed != b->noiseSeed ||
         heroCloudsText(a) != heroCloudsText(b);
}

// Each section the file changed (`before` is the file as last read, `next` as now) goes into
// the world and the running scene; what the player changed elsewhere stays.
bool applyClouds(World& world, SceneDescription& running, const SceneDescription& before,
                 const SceneDescription& next) {
  if (cloudsText(before.clouds) == cloudsText(next.clouds)) return true;
  if (cloudsNeedRestart(before.clouds, next.clouds) || !running.clouds) return false;
  world.view<clouds::ecs::CloudLayer>().each(
      [&](clouds::ecs::CloudLayer& layer) { layer.settings = next.clouds->settings; });
  running.clouds->settings = next.clouds->settings;
  running.clouds->windDirectionDegrees = next.clouds->windDirectionDegrees;
  return true;
}

void applySun(World& world, SceneDescription& running, const SceneDescription& before,
              const SceneDescription& next) {
  const SunDescription& was = before.sun;
  const SunDescription& is = next.sun;
  world.view<TimeOfDay>().each([&](TimeOfDay& t) {
    if (is.timeOfDayHours != was.timeOfDayHours) t.hours = is.timeOfDayHours;
    if (is.hoursPerSecond != was.hoursPerSecond) t.hoursPerSecond = is.hoursPerSecond;
    if (is.maxElevationDegrees != was.maxElevationDegrees)
      t.maxElevationDegrees = is.maxElevationDegrees;
    if (is.azimuthOffsetDegrees != was.azimuthOffsetDegrees)
      t.azimuthOffsetDegrees = is.azimuthOffsetDegrees;
    if (is.illuminance != was.illuminance) t.illuminance = is.illuminance;
  });
  if (is.timeOfDayHours != was.timeOfDayHours) running.sun.timeOfDayHours = is.timeOfDayHours;
  if (is.hoursPerSecond != was.hoursPerSecond) running.sun.hoursPerSecond = is.hoursPerSecond;
  running.sun.maxElevationDegrees = is.maxElevationDegrees;
  running.sun.azimuthOffsetDegrees = is.azimuthOffsetDegrees;
  running.sun.illuminance = is.illuminance;
}

void applyExposureAndFog(World& world, SceneDescription& running, const SceneDescription& before,
                         const SceneDescription& next) {
  const ExposureDescription& was = before.exposure;
  const ExposureDescription& is = next.exposure;
  if (was.automatic != is.automatic || was.ev100 != is.ev100 ||
      was.compensationEv != is.compensationEv || was.adaptationSeconds != is.adaptationSeconds) {
    auto& exposure = world.ctx().get<engine::render::Exposure>();
    exposure.mode = is.automatic ? engine::render::Exposure::Mode::Auto
                                 : engine::render::Exposure::Mode::Manual;
    if (!is.automatic) exposure.ev100 = float(is.ev100);
    exposure.compensationEv = float(is.compensationEv);
    exposure.adaptationSeconds = float(is.adaptationSeconds);
    running.exposure = is;
  }
  if (before.fog && next.fog && running.fog &&
      before.fog->densityPerMetre != next.fog->densityPerMetre) {
    world.ctx().get<engine::render::Fog>().densityPerMetre = float(next.fog->densityPerMetre);
    running.fog = next.fog;
  }
}

// The water's level, colour and clarity (water there before and after: the renderer reads them
// every frame).
void applyWater(World& world, SceneDescription& running, const SceneDescription& before,
                const SceneDescription& next) {
  if (!before.water || !next.water || !running.water) return;
  const WaterDescription& is = *next.water;
  world.ctx().emplaceOrReplace<WaterSurface>(
      WaterSurface{is.levelMetres, glm::vec3(is.colour), is.clarity});
  running.water = is;
}

void applyCamera(World& world, SceneDescription& running, const SceneDescription& before,
                 const SceneDescription& next) {
  const bool preset = next.camera.cloudQuality != before.camera.cloudQuality;
  const bool knobs = next.camera.cloudKnobs != before.camera.cloudKnobs;
  // A target the file no longer gives leaves the running one (the sample's default) alone.
  const bool target = next.camera.frameTargetMilliseconds &&
                      next.camera.frameTargetMilliseconds != before.camera.frameTargetMilliseconds;
  world.view<clouds::ecs::CloudQuality>().each(
      [&](engine::ecs::Entity camera, clouds::ecs::CloudQuality& quality) {
        if (preset) quality.preset = next.camera.cloudQuality;
        if (knobs) quality.knobs = next.camera.cloudKnobs;
        if (!target) return;
        if (*next.camera.frameTargetMilliseconds > 0.0) {
          world.emplaceOrReplace<clouds::ecs::CloudFrameBudget>(
              camera, playerFrameBudget(*next.camera.frameTargetMilliseconds));
        } else {
          world.remove<clouds::ecs::CloudFrameBudget>(camera);
        }
      });
  if (preset) running.camera.cloudQuality = next.camera.cloudQuality;
  if (knobs) running.camera.cloudKnobs = next.camera.cloudKnobs;
  if (target) running.camera.frameTargetMilliseconds = next.camera.frameTargetMilliseconds;
}

// A version of the file: its time and its size. An editor's save caught mid-write (the file
// truncated, then written) has another size once done, though the file's clock, as coarse as
// the kernel's (milliseconds), may not have ticked between the two.
struct FileVersion {
  std::filesystem::file_time_type time{};
  std::uintmax_t bytes = 0;
  bool operator==(const FileVersion&) const = default;
};

// What the hot-reload system keeps between frames.
struct Watch {
  std::filesystem::path file;
  SceneDescription lastRead;  // the file as last read
  FileVersion seen{};
  std::uint64_t frame = 0;

  std::optional<FileVersion> version() const {
    std::error_code timeError, sizeError;
    const auto time = std::filesystem::last_write_time(file, timeError);
    const auto bytes = std::filesystem::file_size(file, sizeError);
    if (timeError || sizeError) return std::nullopt;
    return FileVersion{time, bytes};
  }

  void check(World& world) {
    if (frame++ % kHotReloadCheckFrames != 0) return;
    const auto now = version();
    if (!now || *now == seen) return;
    seen = *now;
    auto& live = world.ctx().get<LiveScene>();
    try {
      const SceneDescription next = loadSceneDescription(file);
      live.reloadStatus =
          file.filename().string() + ": " + applyReloadedScene(world, lastRead, next);
      lastRead = next;
      engine::log::info("scene reloaded: " + live.reloadStatus);
    } catch (const engine::Error& error) {
      live.reloadStatus = std::string(error.what()) + " (the running scene is kept)";
      engine::log::error("scene not reloaded: " + live.reloadStatus);
    }
  }
};

}  // namespace

std::string applyReloadedScene(World& world, const SceneDescription& before,
                               const SceneDescription& next) {
  SceneDescription& running = world.ctx().get<LiveScene>().scene;
  const bool cloudsApplied = applyClouds(world, running, before, next);
  applySun(world, running, before, next);
  applyExposureAndFog(world, running, before, next);
  applyWater(world, running, before, next);
  applyCamera(world, running, before, next);
  // The file's other changes: the new file with the sections applied as they were before.
  SceneDescription rest = next;
  if (cloudsApplied) rest.clouds = before.clouds;
  rest.sun = before.sun;
  rest.exposure = before.exposure;
  if (before.fog && next.fog) rest.fog = before.fog;
  if (before.water && next.water) rest.water = before.water;
  rest.camera.cloudQuality = before.camera.cloudQuality;
  rest.camera.cloudKnobs = before.camera.cloudKnobs;
  rest.camera.frameTargetMilliseconds = before.camera.frameTargetMilliseconds;
  if (sceneJson(rest) == sceneJson(before)) return "applied";
  return "applied; other changes (terrain, atmosphere, storm, hero clouds, the camera's start, "
         "shadows, god rays or water on or off) take effect at restart";
}

void installSceneHotReload(engine::ecs::Scheduler& scheduler, const SceneDescription& scene) {
  Watch watch{scene.file, loadSceneDescription(scene.file), {}, 0};
  if (const auto now = watch.version()) watch.seen = *now;
  scheduler.add(engine::ecs::Phase::Input, "scene hot reload",
                [watch](World& world) mutable { watch.check(world); });
}

}  // namespace sample
