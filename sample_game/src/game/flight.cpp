#include "game/flight.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "engine/ecs/events.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/world.h"
#include "engine/platform/input.h"
#include "engine/render/scene_components.h"
#include "game/game_components.h"
#include "game/terrain_height.h"
#include "game/water.h"

namespace sample {
namespace {

using engine::platform::InputState;
using engine::platform::Key;
using engine::render::Camera;

constexpr double kPitchRate = 0.9;  // rad/s at full deflection
constexpr double kRollRate = 1.6;
constexpr double kYawRate = 0.7;
constexpr double kMouseRadiansPerPixel = 0.0025;
constexpr double kThrottleRate = 1.2;  // speed multiplies by e^(rate * t) while held

glm::dquat poseOrientation(const SetCameraPose& pose) {
  const glm::dquat yaw = glm::angleAxis(glm::radians(pose.yawDegrees), glm::dvec3(0, 1, 0));
  const glm::dquat pitch = glm::angleAxis(glm::radians(pose.pitchDegrees), glm::dvec3(1, 0, 0));
  const glm::dquat roll = glm::angleAxis(glm::radians(pose.rollDegrees), glm::dvec3(0, 0, 1));
  return yaw * pitch * roll;
}

}  // namespace

void installFlight(engine::ecs::Scheduler& scheduler) {
  scheduler.add(engine::ecs::Phase::Input, "flight controls", [](engine::ecs::World& world) {
    const InputState& input = world.ctx().get<InputState>();
    const double dt = world.ctx().get<engine::ecs::FrameTime>().deltaSeconds;
    world.view<Aircraft, Camera>().each([&](Aircraft& aircraft, Camera& camera) {
      double throttle = 0.0;
      if (input.isDown(Key::W)) throttle += 1.0;
      if (input.isDown(Key::S)) throttle -= 1.0;
      if (throttle != 0.0) {
        // Multiplicative, so the same key works from 5 m/s to supersonic; from a standstill it
        // first gets a push.
        const double speed = std::max(aircraft.speedMetresPerSecond, 5.0);
        aircraft.speedMetresPerSecond = speed * std::exp(throttle * kThrottleRate * dt);
        if (throttle < 0.0 && aircraft.speedMetresPerSecond < 5.5)
          aircraft.speedMetresPerSecond = 0.0;
      }
      aircraft.speedMetresPerSecond =
          std::clamp(aircraft.speedMetresPerSecond, aircraft.minSpeed, aircraft.maxSpeed);

      double pitch = 0.0, roll = 0.0, yaw = 0.0;
      if (input.isDown(Key::Up)) pitch -= 1.0;  // nose down, like a stick pushed forward
      if (input.isDown(Key::Down)) pitch += 1.0;
      if (input.isDown(Key::Left)) roll += 1.0;
      if (input.isDown(Key::Right)) roll -= 1.0;
      if (input.isDown(Key::A) || input.isDown(Key::Q)) yaw += 1.0;
      if (input.isDown(Key::D) || input.isDown(Key::E)) yaw -= 1.0;
      glm::dquat delta = glm::angleAxis(pitch * kPitchRate * dt, glm::dvec3(1, 0, 0)) *
                         glm::angleAxis(roll * kRollRate * dt, glm::dvec3(0, 0, 1)) *
                         glm::angleAxis(yaw * kYawRate * dt, glm::dvec3(0, 1, 0));
      if (input.mouseCaptured) {
        delta = delta *
                glm::angleAxis(-input.mouseDeltaY * kMouseRadiansPerPixel, glm::dvec3(1, 0, 0)) *
                glm::angleAxis(-input.mouseDeltaX * kMouseRadiansPerPixel, glm::dvec3(0, 1, 0));
      }
      camera.orientation = glm::normalize(camera.orientation * delta);
    });
  });

  scheduler.add(
      engine::ecs::Phase::Simulate, "flight dynamics",
      [reader = engine::ecs::EventReader<SetCameraPose>{}](engine::ecs::World& world) mutable {
        const double dt = world.ctx().get<engine::ecs::FrameTime>().deltaSeconds;
        const InputState& input = world.ctx().get<InputState>();
        const auto* terrain = world.ctx().tryGet<TerrainHeightField>();
        const auto* water = world.ctx().tryGet<WaterSurface>();
        auto& poses = world.events<SetCameraPose>();
        world.view<Aircraft, Camera>().each([&](Aircraft& aircraft, Camera& camera) {
          camera.cut = false;
          for (const SetCameraPose& pose : reader.read(poses)) {
            camera.position = pose.position;
            camera.orientation = poseOrientation(pose);
            if (pose.speedMetresPerSecond)
              aircraft.speedMetresPerSecond = *pose.speedMetresPerSecond;
            camera.cut = true;  // a teleport: temporal effects must not blend across it
          }
          const double boost = input.isDown(Key::LeftShift) ? 4.0 : 1.0;
          camera.position +=
              engine::render::forwardOf(camera) * (aircraft.speedMetresPerSecond * boost * dt);
          // The floor: the terrain, or the water over it (a pilot skims a lake, never dives).
          double ground =
              terrain != nullptr ? terrain->heightAt(camera.position.x, camera.position.z) : 0.0;
          if (water != nullptr) ground = std::max(ground, water->levelMetres);
          camera.position.y = std::clamp(camera.position.y, ground + aircraft.groundClearanceMetres,
                                         aircraft.ceilingMetres);
        });
      });
}

}  // namespace sample
