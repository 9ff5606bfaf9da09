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

void CloudsModule::install(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) {
  world.ctx().emplaceOrReplace<CloudRendererRef>();
  scheduler.add(engine::ecs::Phase::PreRender, "clouds: frame inputs", [](engine::ecs::World& w) {
    CloudRenderer* renderer = w.ctx().get<CloudRendererRef>().renderer;
    if (renderer == nullptr) return;
    w.view<const CloudLayer>().each([&](const CloudLayer& layer) { renderer->settings() = layer.settings; });
    clouds::FrameInputs& in = renderer->frameInputs();
    in.previousView = in.view;
    in.previousProjection = in.projection;
    in.previousCameraPosition = in.cameraPosition;
    w.view<const render::Camera>().each([&](const render::Camera& camera) {
      in.view = render::viewRotation(camera);
      in.cameraPosition = camera.position;
      in.reset = camera.cut;
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
  });
}

}  // namespace clouds::ecs
