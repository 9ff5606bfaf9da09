#pragma once
// "cloud quality keys" (Input): the number keys 1-5 pick the camera's cloud preset, Low,
// Medium, High, Ultra or Reference (Reference is the converged ground truth: seconds per frame
// on a CPU device, for comparing by eye).
#include "engine/ecs/scheduler.h"

namespace sample {

void installCloudQualityControls(engine::ecs::Scheduler& scheduler);

}  // namespace sample
