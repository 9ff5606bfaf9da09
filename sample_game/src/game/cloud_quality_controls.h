#pragma once
// "cloud quality keys" (Input): the number keys 1-5 fix the camera's cloud preset, Low,
// Medium, High, Ultra or Reference (Reference is the converged ground truth: seconds per frame
// on a CPU device, for comparing by eye), and so end its frame budget; G gives the camera a
// frame budget of `frameTargetMilliseconds` again (the governor then picks the preset), or
// takes it away.
#include "clouds/ecs/frame_budget.h"
#include "engine/ecs/scheduler.h"

namespace sample {

// The budget the sample gives its camera: a player sees the wall clock, and on a CPU rasteriser
// the wall time's median can sit under the target while one frame in five runs over it, so the
// governor holds nine frames in ten (the 0.9 quantile of the wall time) to the target.
clouds::ecs::CloudFrameBudget playerFrameBudget(double targetMilliseconds);

void installCloudQualityControls(engine::ecs::Scheduler& scheduler, double frameTargetMilliseconds);

}  // namespace sample
