#pragma once
// Flying: the "flight controls" system (Input phase) turns the frame's InputState into the
// aircraft's throttle and rotation; "flight dynamics" (Simulate) moves it and keeps it above
// the terrain and below the ceiling; camera-pose events (scripts, tests) teleport it.
//
// Keys: W/S throttle, Shift boost, Up/Down pitch, Left/Right roll, A/D yaw (Q/E too), mouse
// (captured) pitch/yaw.
#include "engine/ecs/scheduler.h"

namespace sample {

void installFlight(engine::ecs::Scheduler& scheduler);

}  // namespace sample
