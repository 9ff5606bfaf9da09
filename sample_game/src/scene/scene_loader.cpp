#include "scene/scene_loader.h"

#include <cmath>
#include <cstdio>

#include "atmosphere/ecs/atmosphere_components.h"
#include "atmosphere/ecs/atmosphere_module.h"
#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/clouds_module.h"
#include "clouds/ecs/frame_budget.h"
#include "clouds/ecs/lightning.h"
#include "clouds/vdb_import.h"
#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/ecs/frame_time.h"
#include "engine/platform/input.h"
#include "engine/render/exposure.h"
#include "engine/render/scene_components.h"
#include "game/cloud_quality_controls.h"
#include "game/exposure_control.h"
#include "game/flight.h"
#include "game/game_components.h"
#include "game/terrain_height.h"
#include "game/terrain_placement.h"
#include "game/time_of_day.h"
#include "game/water.h"
#include "render/terrain_materials.h"

namespace sample {

using namespace engine;

namespace {

glm::dquat orientationFrom(double yawDegrees, double pitchDegrees) {
  return glm::angleAxis(glm::radians(yawDegrees), glm::dvec3(0, 1, 0)) *
         glm::angleAxis(glm::radians(pitchDegrees), glm::dvec3(1, 0, 0));
}

// A hero cloud's asset: an OpenVDB file imported (its warnings logged), or an NVDF read.
std::shared_ptr<const clouds::NvdfVolume> loadHeroAsset(const std::filesystem::path& path) {
  clouds::Error error;
  std::optional<clouds::NvdfVolume> volume;
  if (path.extension() == ".vdb") {
    clouds::VdbImportReport report;
    volume = clouds::importVdb(path, {}, &report, &error);
    for (const std::string& warning : report.warnings) engine::log::warning(warning);
  } else {
    volume = clouds::readNvdf(path, &error);
  }
  if (!volume) throw engine::Error(error.message);
  char line[160];
  std::snprintf(line, sizeof(line), ": %ux%ux%u voxels of %g m, %.1f MiB on the GPU",
                volume->size.x, volume->size.y, volume->size.z, double(volume->voxelMetres),
                double(volume->deviceBytes()) / (1024.0 * 1024.0));
  engine::log::info("hero cloud " + path.string() + line);
  return std::make_shared<const clouds::NvdfVolume>(std::move(*volume));
}

// Where a user's cloud goes: ahead on the camera's line of sight, far enough that the whole
// cloud is in front of the camera, its base level with the camera (not in the hills below it).
clouds::HeroCloud inFrontOfTheCamera(const clouds::NvdfVolume& volume,
                                     const CameraDescription& camera) {
  const glm::dvec3 lo(volume.boundsMinMetres());
  const glm::dvec3 hi(volume.boundsMaxMetres());
  const double radius = 0.5 * glm::length(hi - lo);
  const glm::dvec3 forward =
      orientationFrom(camera.yawDegrees, camera.pitchDegrees) * glm::dvec3(0.0, 0.0, -1.0);
  clouds::HeroCloud cloud;
  cloud.positionMetres = camera.position + forward * (1.5 * radius + 100.0) - 0.5 * (lo + hi);
  cloud.positionMetres.y = camera.position.y - lo.y;
  return cloud;
}

}  // namespace

LoadedHeroClouds loadHeroClouds(SceneDescription& scene, const std::filesystem::path& shippedDir,
                                const std::optional<std::filesystem::path>& userCloud) {
  LoadedHeroClouds loaded;
  std::vector<std::filesystem::path> paths;  // of loaded.assets: one load per file
  const auto assetIndex = [&](const std::filesystem::path& path) {
    for (std::size_t i = 0; i < paths.size(); ++i) {
      if (paths[i] == path) return static_cast<std::uint32_t>(i);
    }
    loaded.assets.push_back(loadHeroAsset(path));
    paths.push_back(path);
    return static_cast<std::uint32_t>(paths.size() - 1);
  };
  if (scene.clouds) {
    for (const HeroCloudDescription& hero : scene.clouds->heroClouds) {
      clouds::HeroCloud cloud;
      cloud.asset =
          assetIndex(hero.shipped.empty() ? hero.file : shippedDir / (hero.shipped + ".nvdf"));
      cloud.positionMetres = hero.positionMetres;
      cloud.scale = static_cast<float>(hero.scale);
      cloud.yawRadians = static_cast<float>(glm::radians(hero.yawDegrees));
      loaded.placements.push_back({cloud, hero.lifecycle});
    }
  }
  if (userCloud) {
    const std::uint32_t asset = assetIndex(*userCloud);
    clouds::HeroCloud cloud = inFrontOfTheCamera(*loaded.assets[asset], scene.camera);
    cloud.asset = asset;
    const glm::dvec3& p = cloud.positionMetres;
    engine::log::info("hero cloud " + userCloud->string() + ": placed with its origin at (" +
                      std::to_string(std::lround(p.x)) + ", " + std::to_string(std::lround(p.y)) +
                      ", " + std::to_string(std::lround(p.z)) + ") m, ahead of the camera");
    loaded.placements.push_back({cloud, std::nullopt});
    HeroCloudDescription described;
    described.file = *userCloud;
    described.positionMetres = cloud.positionMetres;
    if (!scene.clouds) scene.clouds = CloudDescription{};
    scene.clouds->heroClouds.push_back(described);
  }
  return loaded;
}

std::optional<LoadedTerrain> loadTerrain(
    const SceneDescription& scene, const std::filesystem::path& defaultTerrain,
    const std::optional<std::filesystem::path>& terrainOverride) {
  std::optional<std::filesystem::path> path = terrainOverride;
  if (!path && scene.terrain) {
    path = scene.terrain->gltf == "default" ? defaultTerrain : scene.terrain->gltf;
  }
  if (!path) return std::nullopt;
  auto mesh = std::make_shared<assets::MeshData>(assets::loadGltfMesh(*path));
  const double scale = placeTerrain(*mesh);
  log::info("terrain " + path->string() + ": " + std::to_string(mesh->positions.size()) +
            " vertices, " + std::to_string(mesh->indices.size() / 3) + " triangles" +
            (scale != 1.0 ? ", scaled by " + std::to_string(scale) : std::string()));
  return LoadedTerrain{*path, mesh};
}

void populateScene(ecs::App& app, const SceneDescription& scene,
                   const std::optional<LoadedTerrain>& terrain,
                   const LoadedHeroClouds& heroClouds) {
  ecs::World& world = app.world();
  world.ctx().emplaceOrReplace<ecs::FrameTime>();
  world.ctx().emplaceOrReplace<platform::InputState>();
  world.ctx().emplaceOrReplace<CaptureRequest>();
  world.ctx().emplaceOrReplace<ExitRequest>();
  render::Exposure exposure;
  exposure.mode =
      scene.exposure.automatic ? render::Exposure::Mode::Auto : render::Exposure::Mode::Manual;
  exposure.ev100 = static_cast<float>(scene.exposure.ev100);
  exposure.compensationEv = static_cast<float>(scene.exposure.compensationEv);
  exposure.adaptationSeconds = static_cast<float>(scene.exposure.adaptationSeconds);
  world.ctx().emplaceOrReplace<render::Exposure>(exposure);
  render::Fog fog;
  if (scene.fog) fog.densityPerMetre = static_cast<float>(scene.fog->densityPerMetre);
  world.ctx().emplaceOrReplace<render::Fog>(fog);

  // The player: a camera flown like an aircraft.
  const ecs::Entity player = world.create();
  render::Camera camera;
  camera.position = scene.camera.position;
  camera.orientation = orientationFrom(scene.camera.yawDegrees, scene.camera.pitchDegrees);
  camera.verticalFovRadians = static_cast<float>(glm::radians(scene.camera.verticalFovDegrees));
  world.emplace<render::Camera>(player, camera);
  Aircraft aircraft;
  aircraft.speedMetresPerSecond = scene.camera.speedMetresPerSecond;
  world.emplace<Aircraft>(player, aircraft);
  world.emplace<clouds::ecs::CloudQuality>(
      player, clouds::ecs::CloudQuality{scene.camera.cloudQuality, scene.camera.cloudKnobs});
  if (scene.camera.frameTargetMilliseconds) {
    world.emplace<clouds::ecs::CloudFrameBudget>(
        player, playerFrameBudget(*scene.camera.frameTargetMilliseconds));
  }
  world.emplace<atmosphere::ecs::AtmosphereQuality>(
      player, atmosphere::ecs::AtmosphereQuality{scene.camera.atmosphereQuality});

  // The sun and its clock.
  const ecs::Entity sun = world.create();
  TimeOfDay time;
  time.hours = scene.sun.timeOfDayHours;
  time.hoursPerSecond = scene.sun.hoursPerSecond;
  time.maxElevationDegrees = scene.sun.maxElevationDegrees;
  time.azimuthOffsetDegrees = scene.sun.azimuthOffsetDegrees;
  time.illuminance = scene.sun.illuminance;
  world.emplace<TimeOfDay>(sun, time);
  world.emplace<render::Sun>(sun, sunLightFor(time));
  // Until a sky measures itself, the analytic sky's light.
  world.ctx().emplaceOrReplace<render::SkyLight>(
      skyLightFor(sunDirectionAt(time), time.illuminance));

  // The terrain, for both the renderer and the ground collision.
  if (terrain) {
    world.ctx().emplaceOrReplace<TerrainHeightField>(*terrain->mesh);
    world.ctx().emplaceOrReplace<TerrainMesh>(
        TerrainMesh{terrain->mesh, !scene.terrain || scene.terrain->castsShadows,
                    scene.terrain ? scene.terrain->snowlineMetres : std::nullopt,
                    !scene.terrain || scene.terrain->closeDetail});
    const ecs::Entity entity = world.create();
    world.emplace<TerrainInstance>(entity, TerrainInstance{terrain->path});
  }

  // A lake or sea, for the renderer and the flight's floor.
  if (scene.water) {
    world.ctx().emplaceOrReplace<WaterSurface>(WaterSurface{
        scene.water->levelMetres, glm::vec3(scene.water->colour), scene.water->clarity});
  }

  // The air, as data; the atmosphere module installs only when this exists.
  if (scene.atmosphere) {
    atmosphere::Parameters air = scene.atmosphere->parameters;
    // The ground under the air (its light bounced into the sky and onto cloud bases) is the
    // terrain the scene shows, unless the scene says otherwise.
    if (terrain && !scene.atmosphere->groundAlbedoGiven) {
      air.groundAlbedo = meanTerrainAlbedo(
          *terrain->mesh,
          terrainMaterialsFor(*terrain->mesh,
                              scene.terrain ? scene.terrain->snowlineMetres : std::nullopt));
      char albedo[64];
      std::snprintf(albedo, sizeof(albedo), "%.3f %.3f %.3f", double(air.groundAlbedo.r),
                    double(air.groundAlbedo.g), double(air.groundAlbedo.b));
      engine::log::info(std::string("atmosphere: the ground's albedo, from the terrain: ") +
                        albedo);
    }
    world.emplace<atmosphere::ecs::Atmosphere>(world.create(), atmosphere::ecs::Atmosphere{air});
  }

  // The clouds, as data; the module below installs only when this exists.
  if (scene.clouds) {
    const ecs::Entity layer = world.create();
    world.emplace<clouds::ecs::CloudLayer>(
        layer, clouds::ecs::CloudLayer{scene.clouds->settings, scene.clouds->noiseSeed,
                                       scene.clouds->weatherMap, heroClouds.assets});
    // Changing weather, as data: the layer's look follows its timeline on the game clock.
    if (scene.weather) {
      clouds::ecs::CloudWeather weather{
          scene.weather->schedule.timeline(),
          scene.weather->schedule.states,
          {},
          scheduledWeatherMaps(scene.weather->schedule, scene.clouds->weatherMap)};
      for (const RegionDescription& r : scene.weather->regions) {
        weather.regions.push_back({r.name, r.place, r.schedule.timeline(), r.schedule.states});
      }
      world.emplace<clouds::ecs::CloudWeather>(layer, std::move(weather));
    }
    // Hero clouds, as data: each an entity placing one of the layer's assets.
    for (const PlacedHeroCloud& placed : heroClouds.placements) {
      const ecs::Entity entity = world.create();
      world.emplace<clouds::HeroCloud>(entity, placed.cloud);
      if (placed.lifecycle) world.emplace<clouds::HeroCloudLifecycle>(entity, *placed.lifecycle);
    }
    // A storm, as data: the clouds module adds its lightning system only when this exists.
    if (scene.lightning) {
      world.emplace<clouds::ecs::LightningStorm>(world.create(), scene.lightning->storm);
      for (const clouds::ecs::LightningCell& cell : scene.lightning->storm.cells) {
        const glm::dvec3& p = cell.positionMetres;
        engine::log::info("lightning: a storm cell at (" + std::to_string(std::lround(p.x)) + ", " +
                          std::to_string(std::lround(p.y)) + ", " +
                          std::to_string(std::lround(p.z)) + ") m, reaching " +
                          std::to_string(std::lround(cell.radiusMetres)) + " m");
      }
    }
  }

  // A storm's strike on demand: B.
  if (scene.lightning) {
    app.scheduler().add(ecs::Phase::Input, "lightning controls", [](ecs::World& w) {
      if (w.ctx().get<engine::platform::InputState>().wasPressed(engine::platform::Key::B)) {
        w.events<clouds::ecs::TriggerLightning>().send(clouds::ecs::TriggerLightning{});
      }
    });
  }
  installTimeOfDay(app.scheduler());
  installFlight(app.scheduler());
  installCloudQualityControls(app.scheduler(),
                              scene.camera.frameTargetMilliseconds.value_or(
                                  clouds::ecs::CloudFrameBudget{}.targetMilliseconds));
  // The atmosphere first: its passes draw the sky the clouds' passes read. It installs only
  // with an Atmosphere and a device that can run it; otherwise the analytic sky stands in.
  if (!app.addModule<atmosphere::ecs::AtmosphereModule>()) {
    installAnalyticSky(world, app.scheduler());
  }
  // Installs only with a cloud layer and a device that can run it; otherwise it warns and the
  // scene runs without clouds.
  app.addModule<clouds::ecs::CloudsModule>();
  installExposureControl(app.scheduler());
}

}  // namespace sample
