#include "game/exposure_control.h"

#include <algorithm>

#include "engine/ecs/frame_time.h"
#include "engine/render/exposure.h"
#include "engine/render/scene_components.h"

namespace sample {

using namespace engine;

float meteredEv100(ecs::World& world) {
  double altitude = 0.0;
  world.view<const render::Camera>().each(
      [&](const render::Camera& camera) { altitude = camera.position.y; });
  const auto* transmittance = world.ctx().tryGet<render::SunTransmittance>();
  glm::vec3 sun(0.0f);
  double sunUp = 0.0;
  world.view<const render::Sun>().each([&](const render::Sun& s) {
    sun = render::sunIlluminanceAt(s, transmittance, altitude);
    sunUp = s.direction.y;
  });
  // The sky as drawn, and as its cover makes it at the camera when an effect measures that.
  const render::SkyLight sky = world.ctx().get<render::SkyLight>();
  const auto* covered = world.ctx().tryGet<render::CoveredSkyLight>();
  const double kilolux = render::horizontalIlluminanceKilolux(sun, sunUp, sky, covered, altitude);
  return render::ev100FromIlluminance(kilolux * 1000.0);
}

void installExposureControl(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::PreRender, "auto exposure", [](ecs::World& world) {
    auto& exposure = world.ctx().get<render::Exposure>();
    if (exposure.mode != render::Exposure::Mode::Auto) return;
    // Compensations are in stops of brightness (+1: twice as bright), EV100 the other way.
    const float metered = meteredEv100(world);
    const float target =
        std::clamp(metered - exposure.compensationEv - render::dimLightCompensationEv(metered),
                   exposure.minEv100, exposure.maxEv100);
    const double dt = world.ctx().get<ecs::FrameTime>().deltaSeconds;
    const bool covered = world.ctx().tryGet<render::CoveredSkyLight>() != nullptr;
    const bool atOnce = !exposure.adapted || (covered && !exposure.meteredCovered);
    exposure.ev100 =
        atOnce ? target
               : render::adaptEv100(exposure.ev100, target, dt, exposure.adaptationSeconds);
    exposure.adapted = true;
    exposure.meteredCovered = covered;
  });
}

}  // namespace sample
