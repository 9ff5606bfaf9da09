#include "engine/ecs/events.h"

namespace engine::ecs {

// Out of line so the vtable has one home.
EventQueueBase::~EventQueueBase() = default;

}  // namespace engine::ecs
