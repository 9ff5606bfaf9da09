#include "atmosphere/ecs/atmosphere_frame.h"

#include <algorithm>

#include "atmosphere/ecs/atmosphere_components.h"

namespace atmosphere::ecs {

using namespace engine;

atmosphere::Parameters atmosphereParameters(engine::ecs::World& world) {
  atmosphere::Parameters parameters;
  world.view<const Atmosphere>().each([&](const Atmosphere& a) { parameters = a.parameters; });
  return parameters;
}

atmosphere::Settings atmosphereSettings(engine::ecs::World& world) {
  atmosphere::Quality preset = atmosphere::Quality::Medium;
  world.view<const render::Camera>().each([&](engine::ecs::Entity entity, const render::Camera&) {
    if (const auto* quality = world.tryGet<const AtmosphereQuality>(entity)) {
      preset = quality->preset;
    }
  });
  return atmosphere::settingsFor(preset);
}

atmosphere::FrameInputs atmosphereFrameInputs(engine::ecs::World& world, VkCommandBuffer cmd,
                                              VkExtent2D extent, std::uint64_t frameIndex) {
  atmosphere::FrameInputs in;
  in.commandBuffer = cmd;
  in.renderExtent = extent;
  in.frameIndex = frameIndex;
  const float aspect = float(extent.width) / float(std::max(extent.height, 1u));
  world.view<const render::Camera>().each([&](const render::Camera& camera) {
    in.view = render::viewRotation(camera);
    in.projection = render::projectionOf(camera, aspect);
    in.cameraPosition = camera.position;
  });
  world.view<const render::Sun>().each([&](const render::Sun& sun) {
    in.sunDirection = glm::vec3(sun.direction);
    in.sunIlluminance = sun.illuminance;
  });
  return in;
}

engine::render::SkyLight skyLightFrom(const atmosphere::SkyLighting& measured) {
  engine::render::SkyLight sky;
  sky.zenith = measured.zenith;
  sky.horizon = measured.horizon;
  sky.ground = measured.lower;
  return sky;
}

}  // namespace atmosphere::ecs
