#pragma once
// One way to build components, singletons and events from constructor arguments.
#include <type_traits>
#include <utility>

namespace engine::ecs::detail {

/// T(args...) when a constructor matches, else T{args...} so aggregates such as
/// `struct Position { float x, y; }` work with compilers that lack C++20 parenthesised
/// aggregate initialisation (Clang before 16, and therefore clang-tidy 14). Returns a prvalue,
/// so the result is constructed in place (no move) at the call site.
template <class T, class... Args>
constexpr T construct(Args&&... args) {
  if constexpr (std::is_constructible_v<T, Args&&...>) {
    return T(std::forward<Args>(args)...);
  } else {
    return T{std::forward<Args>(args)...};
  }
}

/// Appends T built from `args` to `vector` (std::vector<T>) and returns it: in place when a
/// constructor matches, else by moving a brace-initialised aggregate.
template <class T, class Vector, class... Args>
T& emplaceBack(Vector& vector, Args&&... args) {
  if constexpr (std::is_constructible_v<T, Args&&...>) {
    return vector.emplace_back(std::forward<Args>(args)...);
  } else {
    return vector.emplace_back(T{std::forward<Args>(args)...});
  }
}

}  // namespace engine::ecs::detail
