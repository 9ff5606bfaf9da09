#pragma once
// Entity handles: a 32-bit slot index plus a 32-bit generation that detects stale handles.
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace engine::ecs {

/// A handle to an entity of a World. Plain value type: copying it copies the handle, never
/// the entity. `index` names a slot in the World; `generation` counts how many times that slot
/// has been recycled, so a handle kept after World::destroy() no longer matches its slot and is
/// reported as not alive, even after the index is handed out again.
///
/// A default-constructed Entity equals Entity::null(), which no World ever returns.
struct Entity {
  static constexpr std::uint32_t kNullIndex = UINT32_MAX;
  static constexpr std::uint32_t kNullGeneration = UINT32_MAX;

  std::uint32_t index = kNullIndex;
  std::uint32_t generation = kNullGeneration;

  /// The handle that refers to no entity.
  static constexpr Entity null() noexcept { return Entity{}; }
  constexpr bool isNull() const noexcept { return index == kNullIndex; }

  /// Index and generation packed into one integer (generation in the high half), e.g. for
  /// hashing or serialising a handle within one session.
  constexpr std::uint64_t toBits() const noexcept {
    return (std::uint64_t{generation} << 32u) | std::uint64_t{index};
  }

  friend constexpr bool operator==(Entity, Entity) noexcept = default;
  /// Orders by index, then generation: arbitrary but total, for sorted containers.
  friend constexpr auto operator<=>(Entity, Entity) noexcept = default;
};

}  // namespace engine::ecs

template <>
struct std::hash<engine::ecs::Entity> {
  std::size_t operator()(engine::ecs::Entity e) const noexcept {
    return std::hash<std::uint64_t>{}(e.toBits());
  }
};
