#pragma once
// Error reporting for misuse of the ECS (stale handles, missing components or singletons).
#include <string_view>

#include "engine/ecs/entity.h"

namespace engine::ecs::detail {

/// Throws engine::Error("<where><<type>>: <what>"), e.g.
/// "World::get<Position>: entity {index 3, generation 1} is not alive".
/// Kept out of line so the templates that call it stay small.
[[noreturn]] void fail(std::string_view where, std::string_view type, std::string_view what);

/// Same, with the entity handle spelled out before `what`.
[[noreturn]] void failEntity(std::string_view where, std::string_view type, Entity entity,
                             std::string_view what);

}  // namespace engine::ecs::detail
