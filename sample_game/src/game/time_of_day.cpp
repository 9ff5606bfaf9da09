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
  sun.illuminance = glm::vec3(static_cast<float>(time.illuminance));
  return sun;
}

glm::vec3 analyticSunTransmittance(double altitudeMetres, const glm::dvec3& sunDirection) {
  const double elevation = sunDirection.y;
  const double airMass = 1.0 / std::max(elevation + 0.05, 0.02);
  // Extinction at sea level, thinning with an 8 km scale height.
  const glm::dvec3 extinction =
      glm::dvec3(0.02, 0.05, 0.12) * std::exp(-std::max(altitudeMetres, 0.0) / 8000.0);
  const double fade = std::clamp((elevation + 0.06) / 0.08, 0.0, 1.0);
  return glm::vec3(glm::exp(-extinction * airMass) * fade);
}

engine::render::SkyLight skyLightFor(const glm::dvec3& sunDirection, double sunKilolux) {
  const float day = static_cast<float>(std::clamp((sunDirection.y + 0.1) / 0.35, 0.0, 1.0));
  const float dusk = static_cast<float>(std::exp(-std::abs(sunDirection.y) * 12.0));
  // Colours of a 127 klx sun, scaled with it.
  const float scale = static_cast<float>(sunKilolux / 127.0) * 10.0f;
  engine::render::SkyLight sky;
  // A moonless night: a few thousandths of a cd/m^2 (before the scale's tenfold).
  const glm::vec3 nightZenith(2e-7f, 3e-7f, 8e-7f);
  const glm::vec3 nightHorizon(4e-7f, 5e-7f, 1e-6f);
  sky.zenith = scale * glm::mix(nightZenith, glm::vec3(0.15f, 0.28f, 0.65f), day);
  sky.horizon = scale * (glm::mix(nightHorizon, glm::vec3(0.55f, 0.62f, 0.75f), day) +
                         glm::vec3(0.5f, 0.22f, 0.05f) * (dusk * day));
  sky.ground = scale * glm::mix(glm::vec3(2e-7f), glm::vec3(0.12f, 0.12f, 0.1f), day);
  return sky;
}

void installAnalyticSky(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) {
  world.ctx().emplaceOrReplace<engine::render::SunTransmittance>(
      engine::render::SunTransmittance{analyticSunTransmittance});
  scheduler.add(engine::ecs::Phase::Simulate, "analytic sky", [](engine::ecs::World& w) {
    w.view<const engine::render::Sun>().each([&](const engine::render::Sun& sun) {
      w.ctx().emplaceOrReplace<engine::render::SkyLight>(
          skyLightFor(sun.direction, double(sun.illuminance.g)));
    });
  });
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
  scheduler.add(engine::ecs::Phase::Simulate, "sun", [](engine::ecs::World& world) {
    const double dt = world.ctx().get<engine::ecs::FrameTime>().deltaSeconds;
    world.view<TimeOfDay, engine::render::Sun>().each(
        [&](TimeOfDay& time, engine::render::Sun& sun) {
          time.hours = std::fmod(time.hours + time.hoursPerSecond * dt + 24.0, 24.0);
          sun = sunLightFor(time);
        });
  });
}

}  // namespace sample
