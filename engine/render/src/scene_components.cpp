#include "engine/render/scene_components.h"

#include "engine/render/camera_math.h"

namespace engine::render {

glm::dvec3 forwardOf(const Camera& camera) {
  return camera.orientation * glm::dvec3(0, 0, -1);
}
glm::dvec3 upOf(const Camera& camera) {
  return camera.orientation * glm::dvec3(0, 1, 0);
}

glm::mat4 viewRotation(const Camera& camera) {
  return lookTo(glm::vec3(0.0f), glm::vec3(forwardOf(camera)), glm::vec3(upOf(camera)));
}

glm::mat4 projectionOf(const Camera& camera, float aspect) {
  return perspectiveReversedZ(camera.verticalFovRadians, aspect, camera.nearMetres);
}

glm::vec3 sunIlluminanceAt(const Sun& sun, const SunTransmittance* transmittance,
                           double altitudeMetres) {
  if (transmittance == nullptr || !transmittance->at) return sun.illuminance;
  return sun.illuminance * transmittance->at(altitudeMetres, sun.direction);
}

}  // namespace engine::render
