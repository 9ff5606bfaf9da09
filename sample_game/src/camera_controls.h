#pragma once
// Input-phase system: turns the frame's InputState into camera and sun changes.
#include "engine/ecs/scheduler.h"

namespace sample {

void installCameraControls(engine::ecs::Scheduler& scheduler);

}  // namespace sample
