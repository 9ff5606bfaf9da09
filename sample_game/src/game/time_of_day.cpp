#include "game/time_of_day.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "engine/ecs/events.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/world.h"
#include "engine/platform/input.h"

namespace sample {

using engine::platform::Key;

glm::dvec3 sunDirectionAt(const TimeOfDay& time) {
  // Hour angle: 0 at noon; the sun moves 15 degrees an hour.
  const double hourAngle = (time.hours - 12.0) / 12.0 * glm::pi<double>();
  const double maxElevation = glm::radians(time.maxElevationDegrees);
  // A tilted circle: the direction at hour angle h on a circle through east, the noon point and
  // west, tilted so noon is at maxElevation above the south horizon.
  const glm::dvec3 east(1.0, 0.0, 0.0);
  const glm::dvec3 noon(0.0, std::sin(maxElevation), std::cos(maxElevation));
  glm::dvec3 d = std::cos(hourAngle) * noon - std::sin(hourAngle) * east;
  const double offset = glm::radians(time.azimuthOffsetDegrees);
  d = glm::dvec3(d.x * std::cos(offset) - d.z * std::sin(offset), d.y,
                 d.x * std::sin(offset) + d.z * std::cos(offset));
  return glm::normalize(d);
}

engine::render::Sun sunLightFor(const TimeOfDay& time) {
  engine::render::Sun sun;
  sun.direction = sunDirectionAt(time);
  const double elevation = sun.direction.y;
  // Air mass grows towards the horizon: blue goes first, then green; below the horizon the sun
  // fades out over a few degrees instead of switching off.
  const double airMass = 1.0 / std::max(elevation + 0.05, 0.02);
  const glm::dvec3 extinction(0.02, 0.05, 0.12);
  const glm::dvec3 colour = glm::exp(-extinction * airMass);
  const double fade = std::clamp((elevation + 0.06) / 0.08, 0.0, 1.0);
  sun.illuminance = glm::vec3(colour * (time.illuminance * fade));
  return sun;
}

engine::render::SkyLight skyLightFor(const glm::dvec3& sunDirection) {
  const float day = static_cast<float>(std::clamp((sunDirection.y + 0.1) / 0.35, 0.0, 1.0));
  const float dusk = static_cast<float>(std::exp(-std::abs(sunDirection.y) * 12.0));
  engine::render::SkyLight sky;
  const glm::vec3 nightZenith(0.002f, 0.003f, 0.008f);
  const glm::vec3 nightHorizon(0.004f, 0.005f, 0.01f);
  sky.zenith = glm::mix(nightZenith, glm::vec3(0.15f, 0.28f, 0.65f), day);
  sky.horizon = glm::mix(nightHorizon, glm::vec3(0.55f, 0.62f, 0.75f), day) +
                glm::vec3(0.5f, 0.22f, 0.05f) * (dusk * day);
  sky.ground = glm::mix(glm::vec3(0.002f), glm::vec3(0.12f, 0.12f, 0.1f), day);
  return sky;
}

void installTimeOfDay(engine::ecs::Scheduler& scheduler) {
  scheduler.add(
      engine::ecs::Phase::Input, "time controls",
      [reader = engine::ecs::EventReader<SetTimeOfDay>{}](engine::ecs::World& world) mutable {
        const auto& input = world.ctx().get<engine::platform::InputState>();
        const double dt = world.ctx().get<engine::ecs::FrameTime>().deltaSeconds;
        auto& events = world.events<SetTimeOfDay>();
        world.view<TimeOfDay>().each([&](TimeOfDay& time) {
          for (const SetTimeOfDay& e : reader.read(events)) time.hours = e.hours;
          // Holding [ or ] runs the clock at two hours a second.
          if (input.isDown(Key::LeftBracket)) time.hours -= 2.0 * dt;
          if (input.isDown(Key::RightBracket)) time.hours += 2.0 * dt;
          if (input.wasPressed(Key::T))
            time.hoursPerSecond = time.hoursPerSecond > 0.0 ? 0.0 : 0.25;
        });
      });
  scheduler.add(engine::ecs::Phase::Simulate, "sun and sky", [](engine::ecs::World& world) {
    const double dt = world.ctx().get<engine::ecs::FrameTime>().deltaSeconds;
    world.view<TimeOfDay, engine::render::Sun>().each(
        [&](TimeOfDay& time, engine::render::Sun& sun) {
          time.hours = std::fmod(time.hours + time.hoursPerSecond * dt + 24.0, 24.0);
          sun = sunLightFor(time);
          world.ctx().emplaceOrReplace<engine::render::SkyLight>(skyLightFor(sun.direction));
        });
  });
}

}  // namespace sample
