#pragma once
// Readable type names for error messages, and dense per-family type ids for O(1) lookups.
#include <atomic>
#include <cstdint>
#include <string_view>
#if !(defined(__GNUC__) || defined(__clang__))
#include <typeinfo>
#endif

namespace engine::ecs {

/// Human-readable name of T (for example "Position" or "game::Velocity"), for error messages
/// and debug output only: the spelling is compiler-specific. The view points at static storage.
template <class T>
constexpr std::string_view typeName() noexcept {
#if defined(__GNUC__) || defined(__clang__)
  // GCC: "... typeName() [with T = Foo; std::string_view = ...]", Clang: "... [T = Foo]".
  // Parsing the signature gives the name without RTTI and without demangling at run time.
  const std::string_view pretty = __PRETTY_FUNCTION__;
  const std::string_view marker = "T = ";
  const std::size_t begin = pretty.find(marker);
  if (begin == std::string_view::npos) return pretty;
  const std::size_t first = begin + marker.size();
  const std::size_t end = pretty.find_first_of(";]", first);
  return pretty.substr(first, end == std::string_view::npos ? end : end - first);
#else
  return typeid(T).name();
#endif
}

namespace detail {

/// Id families: each family numbers its types 0, 1, 2, ... so a World can keep its component
/// pools, context singletons and event queues in vectors indexed by id.
struct ComponentFamily;
struct ContextFamily;
struct EventFamily;

template <class Family>
struct FamilyCounter {
  static std::uint32_t next() noexcept {
    static std::atomic<std::uint32_t> counter{0};
    return counter.fetch_add(1, std::memory_order_relaxed);
  }
};

/// Dense id of T within Family, assigned on first use and stable for the life of the process.
/// Callers strip cv-qualifiers first so `const T` and `T` share an id. Ids are per program
/// image: a World must not be shared across shared-library boundaries that each instantiate
/// these templates.
template <class Family, class T>
std::uint32_t typeIndex() noexcept {
  static const std::uint32_t id = FamilyCounter<Family>::next();
  return id;
}

}  // namespace detail
}  // namespace engine::ecs
