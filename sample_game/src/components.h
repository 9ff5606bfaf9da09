#pragma once
// Components and context singletons of the sample's world.
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>

namespace sample {

// The player's camera. Metres, radians; yaw 0 looks along -Z, positive yaw turns left
// (counter-clockwise seen from above); pitch positive looks up.
struct FlightCamera {
  glm::dvec3 position{0.0, 2.0, 0.0};  // double: the world is tens of kilometres wide
  double yawRadians = 0.0;
  double pitchRadians = 0.0;
  float verticalFovRadians = 1.0f;
};

// The sun, by elevation above the horizon and azimuth (0 = towards -Z, counter-clockwise).
struct SunLight {
  double elevationRadians = 0.6;
  double azimuthRadians = 0.3;
  float illuminance = 1.0f;  // scale of the sun's radiance
};

// Requests to capture the frame being rendered (headless runs, screenshots).
struct CaptureRequest {
  std::optional<std::filesystem::path> stem;  // set for this frame; the renderer clears it
};

// World-space unit vector of the camera's view direction.
glm::dvec3 forwardOf(const FlightCamera& camera);
// World-space unit vector towards the sun.
glm::dvec3 directionOf(const SunLight& sun);

}  // namespace sample
