#pragma once
// Views: iterate the entities that have every one of a set of component types.
#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <tuple>
#include <type_traits>
#include <utility>

#include "engine/ecs/entity.h"
#include "engine/ecs/sparse_set.h"
#include "engine/ecs/storage.h"

namespace engine::ecs {

namespace detail {
template <class T, class... Rest>
inline constexpr bool kUniqueTypes =
    (!std::is_same_v<std::remove_const_t<T>, std::remove_const_t<Rest>> && ...) &&
    kUniqueTypes<Rest...>;
template <class T>
inline constexpr bool kUniqueTypes<T> = true;
}  // namespace detail

/// The entities of a World that have all of Ts, obtained with World::view<A, const B>().
/// A `const` type in Ts gives read-only access to that component. A View is a cheap handle
/// (one pointer per type) that stays usable as long as its World lives; it owns nothing.
///
/// Iteration drives over the smallest of the pools (chosen when each()/begin() is called) and
/// checks membership in the others. The driving pool is walked from the back by index,
/// re-checking its size at every step, which gives these rules inside each() and range-for:
///  - Safe: destroying the current entity, or removing components from it (swap and pop only
///    moves already-visited entities into its place, so nobody is skipped or seen twice).
///  - Safe: adding components to any entity and creating entities. Entities created during the
///    iteration are never visited (their components are appended behind the cursor). An
///    existing entity that gains the missing components is visited if the cursor has not yet
///    passed it, so use a fresh iteration when that matters.
///  - Not safe: destroying other entities or removing their components (an unvisited entity
///    could move behind the cursor or a visited one in front of it). Use
///    World::destroyDeferred() and flushDeferred() for that.
///  - The references passed to the callback are invalidated by any structural change to their
///    pool (adding or removing that component type on any entity): do not use them after one.
template <class... Ts>
class View {
  static_assert(sizeof...(Ts) > 0, "a view needs at least one component type");
  static_assert(detail::kUniqueTypes<Ts...>, "a view lists each component type once");

  template <class T>
  using StorageFor =
      std::conditional_t<std::is_const_v<T>, const Storage<std::remove_const_t<T>>, Storage<T>>;

 public:
  /// Usually created by World::view(); the storages must outlive the view.
  explicit View(StorageFor<Ts>&... storages) noexcept : pools_(&storages...) {}

  /// Calls `fn(Entity, Ts&...)` or `fn(Ts&...)` for every matching entity (const types as
  /// const references). Does not allocate. See the class comment for what `fn` may change.
  template <class Fn>
  void each(Fn&& fn) const {
    if constexpr (sizeof...(Ts) == 1) {
      // One type: walk its storage directly, no membership checks.
      auto& pool = *std::get<0>(pools_);
      for (std::size_t i = pool.size(); i > 0;) {
        --i;
        call(fn, pool.entities()[i], pool.at(i));
        i = std::min(i, pool.size());
      }
    } else {
      const SparseSet& lead = driver();
      for (std::size_t i = lead.size(); i > 0;) {
        --i;
        const Entity entity = lead.entities()[i];
        if (contains(entity)) eachMatch(fn, entity, std::index_sequence_for<Ts...>{});
        i = std::min(i, lead.size());
      }
    }
  }

  /// True when `entity` has every component of the view.
  bool contains(Entity entity) const noexcept {
    return std::apply([entity](const auto*... pool) { return (pool->contains(entity) && ...); },
                      pools_);
  }

  /// Upper bound on the number of matching entities: the size of the smallest pool.
  std::size_t sizeHint() const noexcept { return driver().size(); }

  /// Range-for over matching entities (same order and rules as each()):
  /// `for (Entity e : world.view<A, B>()) { ... }`.
  class Iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = Entity;
    using difference_type = std::ptrdiff_t;
    using pointer = const Entity*;
    using reference = Entity;

    Iterator() = default;
    Entity operator*() const noexcept { return lead_->entities()[next_ - 1]; }
    Iterator& operator++() noexcept {
      next_ = std::min(next_ - 1, lead_->size());
      skipNonMembers();
      return *this;
    }
    void operator++(int) noexcept { ++*this; }
    friend bool operator==(const Iterator& a, const Iterator& b) noexcept {
      return a.next_ == b.next_;
    }

   private:
    friend class View;
    Iterator(const View* view, const SparseSet* lead, std::size_t next) noexcept
        : view_(view), lead_(lead), next_(next) {
      skipNonMembers();
    }
    void skipNonMembers() noexcept {
      while (next_ > 0 && !view_->contains(lead_->entities()[next_ - 1])) --next_;
    }
    const View* view_ = nullptr;
    const SparseSet* lead_ = nullptr;
    std::size_t next_ = 0;  // one past the position of the current entity; 0 at the end
  };

  Iterator begin() const noexcept {
    const SparseSet& lead = driver();
    return Iterator(this, &lead, lead.size());
  }
  Iterator end() const noexcept { return Iterator(); }

 private:
  const SparseSet& driver() const noexcept {
    const SparseSet* smallest = std::get<0>(pools_);
    std::apply(
        [&smallest](const auto*... pool) {
          ((smallest = pool->size() < smallest->size() ? pool : smallest), ...);
        },
        pools_);
    return *smallest;
  }

  template <class Fn, std::size_t... I>
  void eachMatch(Fn& fn, Entity entity, std::index_sequence<I...>) const {
    call(fn, entity, std::get<I>(pools_)->at(std::get<I>(pools_)->index(entity))...);
  }

  template <class Fn, class... Components>
  static void call(Fn& fn, Entity entity, Components&... components) {
    if constexpr (std::is_invocable_v<Fn&, Entity, Components&...>) {
      fn(entity, components...);
    } else {
      static_assert(std::is_invocable_v<Fn&, Components&...>,
                    "each() takes fn(Entity, Ts&...) or fn(Ts&...), const types as const&");
      fn(components...);
    }
  }

  std::tuple<StorageFor<Ts>*...> pools_;
};

}  // namespace engine::ecs
