#pragma once
// A scene as data: what a JSON scene file (assets_src/scenes/*.json) describes, read in full
// and validated before anything is created, so nothing starts half-configured.
#include <filesystem>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "clouds/clouds.h"

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
};

struct SunDescription {
  double timeOfDayHours = 13.0;       // [0, 24)
  double hoursPerSecond = 0.0;        // how fast time of day advances (0: frozen)
  double maxElevationDegrees = 65.0;  // at noon
  double azimuthOffsetDegrees = 0.0;  // rotates the sun's path around the vertical
  double illuminance = 10.0;          // scale of the sun's linear RGB illuminance
};

struct TerrainDescription {
  // "default" (the generated terrain) or a .gltf/.glb path relative to the scene file.
  std::filesystem::path gltf;
};

struct CloudDescription {
  clouds::Settings settings;
  std::uint32_t noiseSeed = 1;
  std::optional<std::filesystem::path> weatherMap;  // painted map (PNG), relative to the scene
};

struct AtmosphereDescription {
  double fogDensityPerMetre = 2e-5;
  double exposure = 1.0;
};

struct SceneDescription {
  std::filesystem::path file;
  std::string name;
  CameraDescription camera;
  SunDescription sun;
  std::optional<TerrainDescription> terrain;
  std::optional<CloudDescription> clouds;
  AtmosphereDescription atmosphere;
};

// Reads and validates a scene file. Throws engine::Error "<file>: <json path>: <reason>" for
// unknown keys, wrong types, out-of-range values and missing referenced files.
SceneDescription loadSceneDescription(const std::filesystem::path& file);

}  // namespace sample
