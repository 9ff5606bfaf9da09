#pragma once
// The sample's own components, context singletons and events.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace sample {

// The player's aircraft. It carries the engine::render::Camera on the same entity; this holds
// what flying needs on top.
struct Aircraft {
  double speedMetresPerSecond = 120.0;  // current airspeed
  double minSpeed = 0.0;                // hover is allowed: a slow glide is a camera, not a plane
  double maxSpeed = 900.0;
  double groundClearanceMetres = 5.0;
  double ceilingMetres = 30000.0;
};

// The sun's clock: time of day drives the sun direction, its colour and the sky's.
struct TimeOfDay {
  double hours = 13.0;          // [0, 24)
  double hoursPerSecond = 0.0;  // automatic advance
  double maxElevationDegrees = 65.0;
  double azimuthOffsetDegrees = 0.0;
  double illuminance = 127.0;  // klx above the air
};

// Marks the terrain entity; the renderer loads and draws the mesh.
struct TerrainInstance {
  std::filesystem::path gltf;
};

// Requests for the renderer: capture this frame (headless scripts, the screenshot key).
struct CaptureRequest {
  std::optional<std::filesystem::path> stem;  // set for this frame; the renderer clears it
};

// Set when a script or the window asks to stop after this frame.
struct ExitRequest {
  bool requested = false;
};

// --- Events ---------------------------------------------------------------------------------
// Script and input both speak through these, so headless runs take the same path.

struct SetCameraPose {
  glm::dvec3 position{0.0};
  double yawDegrees = 0.0;
  double pitchDegrees = 0.0;
  double rollDegrees = 0.0;
  std::optional<double> speedMetresPerSecond;
};

struct SetTimeOfDay {
  double hours = 12.0;
};

struct CaptureFrame {
  std::string name;
};

}  // namespace sample
