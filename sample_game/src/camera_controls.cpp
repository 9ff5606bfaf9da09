#include "camera_controls.h"

#include <algorithm>
#include <glm/gtc/constants.hpp>

#include "components.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/world.h"
#include "engine/platform/input.h"

namespace sample {

using engine::platform::InputState;
using engine::platform::Key;

void installCameraControls(engine::ecs::Scheduler& scheduler) {
  scheduler.add(engine::ecs::Phase::Input, "camera controls", [](engine::ecs::World& world) {
    const auto& input = world.ctx().get<InputState>();
    const double dt = world.ctx().get<engine::ecs::FrameTime>().deltaSeconds;
    constexpr double kTurnRadiansPerSecond = 1.2;
    constexpr double kMouseRadiansPerPixel = 0.003;
    world.view<FlightCamera>().each([&](FlightCamera& camera) {
      if (input.isDown(Key::Left)) camera.yawRadians += kTurnRadiansPerSecond * dt;
      if (input.isDown(Key::Right)) camera.yawRadians -= kTurnRadiansPerSecond * dt;
      if (input.isDown(Key::Up)) camera.pitchRadians += kTurnRadiansPerSecond * dt;
      if (input.isDown(Key::Down)) camera.pitchRadians -= kTurnRadiansPerSecond * dt;
      camera.yawRadians -= input.mouseDeltaX * kMouseRadiansPerPixel;
      camera.pitchRadians -= input.mouseDeltaY * kMouseRadiansPerPixel;
      camera.pitchRadians = std::clamp(camera.pitchRadians, -1.5, 1.5);
    });
    world.view<SunLight>().each([&](SunLight& sun) {
      constexpr double kTimeOfDayRadiansPerSecond = 0.4;
      if (input.isDown(Key::LeftBracket)) sun.elevationRadians -= kTimeOfDayRadiansPerSecond * dt;
      if (input.isDown(Key::RightBracket)) sun.elevationRadians += kTimeOfDayRadiansPerSecond * dt;
      sun.elevationRadians = std::clamp(sun.elevationRadians, -0.35, glm::half_pi<double>());
    });
  });
}

}  // namespace sample
