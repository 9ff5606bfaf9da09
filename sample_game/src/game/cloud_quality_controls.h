#pragma once
// "cloud quality keys" (Input): the number keys 1-5 fix the camera's cloud preset, Low,
// Medium, High, Ultra or Reference (Reference is the converged ground truth: seconds per frame
// on a CPU device, for comparing by eye), and so end its frame budget; G gives the camera a
// frame budget of `frameTargetMilliseconds` again (the governor then picks the preset), or
// takes it away.
#include "engine/ecs/scheduler.h"

namespace sample {

void installCloudQualityControls(engine::ecs::Scheduler& scheduler, double frameTargetMilliseconds);

}  // namespace sample
