#include "clouds/ecs/clouds_module.h"

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/cloud_renderer.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"
#include "engine/render/scene_components.h"

namespace clouds::ecs {

using namespace engine;

bool CloudsModule::supported(const engine::ecs::World& world, std::string& reason) const {
  const auto* layers = world.findStorage<CloudLayer>();
  if (layers == nullptr || layers->size() == 0) {
    reason = "the scene has no cloud layer";
    return false;
  }
  return true;
}

void updateFrameInputs(engine::ecs::World& w, clouds::FrameInputs& in,
                       clouds::Settings& settings) {
  clouds::Settings layerSettings;
  w.view<const CloudLayer>().each([&](const CloudLayer& layer) { layerSettings = layer.settings; });
  settings = layerSettings;
  in.previousView = in.view;
  in.previousProjection = in.projection;
  in.previousCameraPosition = in.cameraPosition;
  w.view<const render::Camera>().each([&](engine::ecs::Entity entity, const render::Camera& camera) {
    in.view = render::viewRotation(camera);
    in.cameraPosition = camera.position;
    in.reset = camera.cut;
    if (const auto* quality = w.tryGet<const CloudQuality>(entity)) {
      settings = clouds::settingsFor(quality->preset, layerSettings);
    }
  });
  w.view<const render::Sun>().each([&](const render::Sun& sun) {
    in.sunDirection = glm::vec3(sun.direction);
    in.sunIlluminance = sun.illuminance;
  });
  if (const auto* sky = w.ctx().tryGet<render::SkyLight>()) {
    in.ambientTop = sky->zenith;
    in.ambientBottom = glm::mix(sky->horizon, sky->ground, 0.5f);
  }
  const auto& time = w.ctx().get<engine::ecs::FrameTime>();
  in.timeSeconds = time.elapsedSeconds;
  if (time.frameIndex == 0) in.reset = true;
}

void CloudsModule::install(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) {
  world.ctx().emplaceOrReplace<CloudRendererRef>();
  scheduler.add(engine::ecs::Phase::PreRender, "clouds: frame inputs", [](engine::ecs::World& w) {
    CloudRenderer* renderer = w.ctx().get<CloudRendererRef>().renderer;
    if (renderer == nullptr) return;
    updateFrameInputs(w, renderer->frameInputs(), renderer->settings());
  });
}

}  // namespace clouds::ecs
