#pragma once
// Time of day: "time controls" (Input: [ and ] move the clock, script events set it) and
// "sun and sky" (Simulate: advance the clock, place the sun on a simple daily arc and derive
// the sun's colour and the sky's colours from its elevation).
#include <glm/glm.hpp>

#include "engine/ecs/scheduler.h"
#include "engine/render/scene_components.h"
#include "game/game_components.h"

namespace sample {

void installTimeOfDay(engine::ecs::Scheduler& scheduler);

// The sun direction for a time of day (pure; tested): rises in the east (+X) at 6:00, peaks
// at 12:00 at maxElevation towards the south (+Z), sets in the west at 18:00, below the horizon
// at night. The azimuth offset rotates the arc about the vertical.
glm::dvec3 sunDirectionAt(const TimeOfDay& time);
// Sun illuminance and sky colours for a sun direction (reddened and dimmed near the horizon).
engine::render::Sun sunLightFor(const TimeOfDay& time);
engine::render::SkyLight skyLightFor(const glm::dvec3& sunDirection);

}  // namespace sample
