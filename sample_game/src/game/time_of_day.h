#pragma once
// Time of day: "time controls" (Input: [ and ] move the clock, script events set it) and
// "sun" (Simulate: advance the clock, place the sun on a simple daily arc). The light of the
// sky comes from the atmosphere module when the scene has one; without one, the analytic sky
// (installAnalyticSky) stands in: an air mass that reddens the sun and a gradient sky whose
// colours follow its elevation.
#include <glm/glm.hpp>

#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"
#include "engine/render/scene_components.h"
#include "game/game_components.h"

namespace sample {

void installTimeOfDay(engine::ecs::Scheduler& scheduler);
// The stand-in for an atmosphere: publishes engine::render::SunTransmittance (analyticSun-
// Transmittance) and adds "analytic sky" (Simulate, after "sun"), which writes the SkyLight.
void installAnalyticSky(engine::ecs::World& world, engine::ecs::Scheduler& scheduler);

// The sun direction for a time of day (pure; tested): rises in the east (+X) at 6:00, peaks
// at 12:00 at maxElevation towards the south (+Z), sets in the west at 18:00, below the horizon
// at night. The azimuth offset rotates the arc about the vertical.
glm::dvec3 sunDirectionAt(const TimeOfDay& time);
// The sun of a time of day: its direction, and its white illuminance above the air (klx).
engine::render::Sun sunLightFor(const TimeOfDay& time);
// The analytic sky's transmittance of sunlight to an altitude: an air mass growing towards the
// horizon takes blue first, then green; below the horizon the sun fades over a few degrees.
glm::vec3 analyticSunTransmittance(double altitudeMetres, const glm::dvec3& sunDirection);
// The analytic sky's radiance (kcd/m^2) for a sun direction and its illuminance above the air.
engine::render::SkyLight skyLightFor(const glm::dvec3& sunDirection, double sunKilolux);

}  // namespace sample
