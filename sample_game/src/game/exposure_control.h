#pragma once
// "auto exposure" (PreRender): meters the illuminance the sun (through the scene's air and, with
// a CoveredSkyLight, through the clouds at the camera) and the sky (covered, when measured) put
// on a horizontal surface at the camera and adapts the Exposure singleton towards it
// (engine/render/exposure.h has the response). A manual Exposure is left as it is.
#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"

namespace sample {

void installExposureControl(engine::ecs::Scheduler& scheduler);

// The EV100 the meter reads for the world as it is now (pure; tested).
float meteredEv100(engine::ecs::World& world);

}  // namespace sample
