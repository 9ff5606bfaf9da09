#pragma once
// Umbrella header: the whole engine::ecs public API.
#include "engine/ecs/app.h"
#include "engine/ecs/context.h"
#include "engine/ecs/entity.h"
#include "engine/ecs/events.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/module.h"
#include "engine/ecs/phase.h"
#include "engine/ecs/scheduler.h"
#include "engine/ecs/sparse_set.h"
#include "engine/ecs/storage.h"
#include "engine/ecs/view.h"
#include "engine/ecs/world.h"
