#pragma once
// A scene as data: what a JSON scene file (assets_src/scenes/*.json) describes, read in full
// and validated before anything is created, so nothing starts half-configured.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "atmosphere/atmosphere.h"
#include "clouds/clouds.h"
#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/lightning.h"
#include "clouds/hero_cloud_life.h"
#include "scene/weather_description.h"

namespace sample {

struct CameraDescription {
  glm::dvec3 position{0.0, 600.0, 0.0};  // metres, y = altitude
  double yawDegrees = 0.0;               // 0 looks along -Z, counter-clockwise from above
  double pitchDegrees = 0.0;
  double verticalFovDegrees = 65.0;
  double speedMetresPerSecond = 120.0;
  // Cost/accuracy preset of this camera's clouds ("low", "medium", "high", "ultra",
  // "reference"); --quality and the number keys 1-5 override it.
  clouds::Quality cloudQuality = clouds::Quality::Medium;
  // The preset's march knobs tuned by hand ("cloudKnobs": maxViewSteps, viewStepMetres,
  // lightSteps, transmittanceCutoff; each absent keeps the preset's). A scene with any is not
  // governed: the governor's rungs are the presets as they are.
  clouds::ecs::CloudQualityKnobs cloudKnobs;
  // Milliseconds a frame (wall clock, nine frames in ten: playerFrameBudget()) that a governor
  // holds by choosing the cloud preset (from cloudQuality on); 0: none, the preset stays.
  // Unset: the sample's default (a window's runs are governed, headless ones not);
  // --frame-target-ms and --quality override it.
  std::optional<double> frameTargetMilliseconds;
  // Cost/accuracy preset of this camera's atmosphere ("low", "medium", "high", "reference").
  atmosphere::Quality atmosphereQuality = atmosphere::Quality::Medium;
};

struct SunDescription {
  double timeOfDayHours = 13.0;       // [0, 24)
  double hoursPerSecond = 0.0;        // how fast time of day advances (0: frozen)
  double maxElevationDegrees = 65.0;  // at noon
  double azimuthOffsetDegrees = 0.0;  // rotates the sun's path around the vertical
  double illuminance = 127.0;  // klx at the top of the atmosphere (white); the air reddens it
};

struct TerrainDescription {
  // "default" (the generated terrain) or a .gltf/.glb path relative to the scene file.
  std::filesystem::path gltf;
  // Whether mountains shade the clouds and cast long shadows on the terrain (through the
  // clouds' shadow map, so only in a scene whose clouds cast shadows).
  bool castsShadows = true;
  // Where snow starts to lie (m above sea level); unset: 70% of the way from the mesh's lowest
  // to its highest point.
  std::optional<double> snowlineMetres;
  // The close-up detail (terrain_material.h: colour by material at the scales a pixel resolves,
  // and the 3 m octave's relief): off, the ground is what a pixel covering 15 m of it sees
  // everywhere, and the terrain's fragments pay nothing for it (a scene seen from high up).
  bool closeDetail = true;
};

// A hero cloud (the clouds module's voxel clouds) the scene places.
struct HeroCloudDescription {
  // A shipped cloud by name (kShippedHeroClouds: baked by assets_src/hero_clouds), or else an
  // .nvdf or OpenVDB (.vdb) file, relative to the scene file.
  std::string shipped;
  std::filesystem::path file;
  glm::dvec3 positionMetres{0.0};  // world position of the cloud's own origin
  double scale = 1.0;              // [0.01, 100]
  double yawDegrees = 0.0;         // a turn about the vertical
  // Its life on the game clock: grows, stays, dissipates (and again, when it repeats).
  std::optional<clouds::HeroCloudLifecycle> lifecycle;
};
inline constexpr const char* kShippedHeroClouds[] = {"towering_cumulus", "cumulonimbus", "arch"};

// The god-ray samples a scene's "godRays": true gives the layer (a quality preset then picks
// its own count; 0 is off).
inline constexpr std::uint32_t kSceneGodRaySamples = 16;

struct CloudDescription {
  clouds::Settings settings;
  // The wind's heading as the scene gives it (settings.windDirection is made from it), so a
  // scene written back says the very same angle.
  double windDirectionDegrees = 0.0;
  std::uint32_t noiseSeed = 1;
  std::optional<std::filesystem::path> weatherMap;  // painted map (PNG), relative to the scene
  std::vector<HeroCloudDescription> heroClouds;     // at most 64
};

// The physical sky and haze (the atmosphere module): a named preset ("earth", "hazy") with
// any of its parameters overridden.
struct AtmosphereDescription {
  atmosphere::Parameters parameters;
  // Whether the scene gives the ground's albedo; if not, a scene with terrain takes the
  // terrain's mean (meanTerrainAlbedo()), so the sky and the clouds see the ground it shows.
  bool groundAlbedoGiven = false;
};

// The cheap alternative to an atmosphere: the renderer's gradient sky and exponential fog.
struct FogDescription {
  double densityPerMetre = 2e-5;
};

// A lake or sea at one level (the renderer's water: shaders/water_surface.h); the terrain below
// it is its bed, and beyond the terrain it is deep.
struct WaterDescription {
  double levelMetres = 0.0;               // above sea level
  glm::dvec3 colour{0.012, 0.03, 0.035};  // the water body's albedo
  double clarity = 0.35;                  // the share of the bed seen straight down
};

struct ExposureDescription {
  bool automatic = true;        // "auto": metered from the sun and sky; "manual": ev100
  double ev100 = 15.0;          // manual
  double compensationEv = 0.0;  // auto
  double adaptationSeconds = 0.5;
};

// A storm: the cells where lightning glows in the clouds, its rate, seed and kind of strikes.
struct LightningDescription {
  clouds::ecs::LightningStorm storm;
};

struct SceneDescription {
  std::filesystem::path file;
  std::string name;
  CameraDescription camera;
  SunDescription sun;
  std::optional<TerrainDescription> terrain;
  std::optional<CloudDescription> clouds;
  std::optional<WeatherDescription> weather;        // with clouds only
  std::optional<LightningDescription> lightning;    // with clouds only
  std::optional<AtmosphereDescription> atmosphere;  // exclusive with fog
  std::optional<FogDescription> fog;
  std::optional<WaterDescription> water;
  ExposureDescription exposure;
};

// Reads and validates a scene file. Throws engine::Error "<file>: <json path>: <reason>" for
// unknown keys, wrong types, out-of-range values and missing referenced files.
SceneDescription loadSceneDescription(const std::filesystem::path& file);

}  // namespace sample
