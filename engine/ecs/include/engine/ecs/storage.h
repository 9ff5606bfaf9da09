#pragma once
// Component storage: a sparse set of entities plus a parallel dense array of components.
#include <cstddef>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/ecs/construct.h"
#include "engine/ecs/entity.h"
#include "engine/ecs/errors.h"
#include "engine/ecs/sparse_set.h"
#include "engine/ecs/type_info.h"

namespace engine::ecs {

/// Holds every T component of one World: components()[i] belongs to entities()[i].
///
/// T may be any non-const object type that is move-constructible and move-assignable,
/// including std::string, containers and move-only types such as std::unique_ptr. Each
/// component is destroyed exactly once: on remove(), clear(), or when the storage dies.
///
/// Ownership: the storage owns its components. Invalidation: references and pointers to
/// components are invalidated by any insertion (the array may grow) and by any removal (the
/// last component moves into the hole). Access is O(1).
template <class T>
class Storage final : public SparseSet {
  static_assert(std::is_object_v<T> && !std::is_const_v<T> && !std::is_volatile_v<T>,
                "components must be non-const, non-volatile object types");
  static_assert(std::is_move_constructible_v<T> && std::is_move_assignable_v<T>,
                "components must be move-constructible and move-assignable");

 public:
  using ValueType = T;

  Storage() = default;
  ~Storage() override = default;

  /// Hidden: every member of a storage needs a component, so insert through emplace().
  void insert(Entity entity) = delete;

  /// Constructs a T for `entity` from `args` and returns it. Throws engine::Error naming T
  /// when the entity already has one or is null, and engine::Error when another generation of
  /// its index is present (a stale handle). Strong guarantee.
  template <class... Args>
  T& emplace(Entity entity, Args&&... args) {
    if (entity.isNull()) detail::failEntity("emplace", typeName<T>(), entity, "is null");
    if (contains(entity)) detail::failEntity("emplace", typeName<T>(), entity, "already has one");
    pushBack(entity);
    try {
      return detail::emplaceBack<T>(components_, std::forward<Args>(args)...);
    } catch (...) {
      popBack();
      throw;
    }
  }

  /// Like emplace(), but when the entity already has a T it is replaced by T(args...).
  template <class... Args>
  T& emplaceOrReplace(Entity entity, Args&&... args) {
    if (!contains(entity)) return emplace(entity, std::forward<Args>(args)...);
    T& existing = components_[index(entity)];
    existing = detail::construct<T>(std::forward<Args>(args)...);
    return existing;
  }

  /// The component of `entity`; throws engine::Error naming T when absent.
  T& get(Entity entity) {
    if (!contains(entity)) detail::failEntity("get", typeName<T>(), entity, "has none");
    return components_[index(entity)];
  }
  const T& get(Entity entity) const {
    if (!contains(entity)) detail::failEntity("get", typeName<T>(), entity, "has none");
    return components_[index(entity)];
  }

  /// The component of `entity`, or nullptr when absent.
  T* tryGet(Entity entity) noexcept {
    return contains(entity) ? &components_[index(entity)] : nullptr;
  }
  const T* tryGet(Entity entity) const noexcept {
    return contains(entity) ? &components_[index(entity)] : nullptr;
  }

  /// Component at dense `position` (unchecked; position < size()).
  T& at(std::size_t position) noexcept { return components_[position]; }
  const T& at(std::size_t position) const noexcept { return components_[position]; }

  /// The components, densely packed, parallel to entities().
  std::span<T> components() noexcept { return components_; }
  std::span<const T> components() const noexcept { return components_; }

  void reserve(std::size_t capacity) override {
    SparseSet::reserve(capacity);
    components_.reserve(capacity);
  }

 private:
  void swapAndPopPayload(std::size_t position) override {
    if (position + 1 != components_.size()) components_[position] = std::move(components_.back());
    components_.pop_back();
  }
  void clearPayload() noexcept override { components_.clear(); }

  std::vector<T> components_;
};

}  // namespace engine::ecs
