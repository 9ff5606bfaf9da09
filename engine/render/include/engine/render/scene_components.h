#pragma once
// Components every renderer of the engine understands, independent of any game: the viewpoint,
// the sun, the sky's light and the atmosphere. Effect adapters (the clouds) read these to build
// their per-frame inputs; games write them.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace engine::render {

// The viewpoint. World: metres, Y up, a flat map tens of kilometres wide, so the position is
// double precision and rendering is camera-relative. `orientation` rotates camera space (looking
// down -Z with +Y up) into world space.
struct Camera {
  glm::dvec3 position{0.0, 2.0, 0.0};
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  float verticalFovRadians = 1.1f;
  float nearMetres = 0.5f;
  bool cut = false;  // the camera jumped this frame: temporal effects drop their history
};

glm::dvec3 forwardOf(const Camera& camera);
glm::dvec3 upOf(const Camera& camera);
// World -> view with the camera at the origin (camera-relative rendering).
glm::mat4 viewRotation(const Camera& camera);
// View -> clip for an image of `aspect` = width / height: reversed-Z, infinite far plane
// (camera_math.h). Every pass that draws or traces with the camera uses this one.
glm::mat4 projectionOf(const Camera& camera, float aspect);

// The sun as a directional light.
struct Sun {
  glm::dvec3 direction{0.0, 1.0, 0.0};  // unit, towards the sun
  glm::vec3 illuminance{10.0f};         // linear RGB, the renderer's radiometric unit
};

// Sky radiance used for ambient light and as the backdrop: zenith and horizon colours, and the
// light bounced up from the ground.
struct SkyLight {
  glm::vec3 zenith{0.15f, 0.28f, 0.65f};
  glm::vec3 horizon{0.55f, 0.62f, 0.75f};
  glm::vec3 ground{0.12f, 0.12f, 0.1f};
};

struct Atmosphere {
  float fogDensityPerMetre = 2e-5f;  // exponential haze over distance (aerial perspective hook)
  float exposure = 1.0f;             // linear multiplier before tonemapping
};

}  // namespace engine::render
