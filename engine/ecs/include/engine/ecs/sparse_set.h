#pragma once
// Paged sparse set of entities: the index structure under every component storage.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "engine/ecs/entity.h"

namespace engine::ecs {

/// A set of entity handles with O(1) insert, remove and lookup and a densely packed handle
/// array for iteration.
///
/// Layout: the sparse array maps an entity index to its position in the dense array. It is
/// split into pages of kPageSize entries allocated on first touch, so one entity with a huge
/// index costs one page, not an array as long as the index. The dense array stores full handles
/// (index and generation), so contains() rejects a stale handle whose index was reused.
///
/// Removal moves the last element into the hole and pops ("swap and pop"): O(1), order not
/// stable. Derived storages keep a payload array parallel to the dense array and mirror every
/// move through the protected hooks.
///
/// Memory: pages and dense capacity are kept until destruction (clear() keeps them), so a set
/// that has reached its working size never allocates again.
/// Invalidation: entities() spans are invalidated by insertion (reallocation) and removal.
/// Not thread-safe; concurrent reads without writers are fine.
class SparseSet {
 public:
  static constexpr std::uint32_t kPageShift = 12;
  static constexpr std::uint32_t kPageSize = 1u << kPageShift;  // 4096 entries, 16 KiB a page

  SparseSet() = default;
  virtual ~SparseSet();
  SparseSet(const SparseSet&) = delete;
  SparseSet& operator=(const SparseSet&) = delete;

  /// True when this exact handle (index and generation) is in the set.
  bool contains(Entity entity) const noexcept {
    const std::uint32_t* page = findPage(entity.index);
    if (page == nullptr) return false;
    const std::uint32_t position = page[entity.index & kPageMask];
    return position != kAbsent && dense_[position] == entity;
  }

  /// Position of `entity` in entities(). Precondition: contains(entity).
  std::size_t index(Entity entity) const noexcept {
    return findPage(entity.index)[entity.index & kPageMask];
  }

  std::size_t size() const noexcept { return dense_.size(); }
  bool empty() const noexcept { return dense_.empty(); }
  std::size_t capacity() const noexcept { return dense_.capacity(); }
  /// Number of sparse pages allocated so far (memory diagnostics and tests).
  std::size_t pageCount() const noexcept;

  /// The members, densely packed, in storage order (which removals permute).
  std::span<const Entity> entities() const noexcept { return dense_; }

  /// Inserts `entity` (plain sets only; storages insert through emplace()). Throws engine::Error
  /// for a null handle, one already present, or one whose index is held by another generation.
  /// Strong guarantee.
  void insert(Entity entity);

  /// Removes `entity` by swap and pop; returns false (and does nothing) when it is absent.
  bool remove(Entity entity);

  /// Removes every member. Keeps pages and capacity.
  void clear() noexcept;

  /// Grows dense capacity so `capacity` members fit without reallocation.
  virtual void reserve(std::size_t capacity);

 protected:
  /// Appends `entity` to the dense array. Precondition: !contains(entity), entity not null.
  /// Throws engine::Error when another generation of the same index is present. Strong
  /// guarantee: on failure the set is unchanged apart from a new empty page.
  void pushBack(Entity entity);
  /// Undoes the latest pushBack(); used when constructing the matching payload throws.
  void popBack() noexcept;

  /// Called by remove() before the dense array changes: replace the payload at `position` by
  /// the last payload (unless they are the same) and destroy the last one.
  virtual void swapAndPopPayload(std::size_t position);
  /// Called by clear(): destroy every payload.
  virtual void clearPayload() noexcept;

 private:
  static constexpr std::uint32_t kPageMask = kPageSize - 1;
  static constexpr std::uint32_t kAbsent = UINT32_MAX;

  const std::uint32_t* findPage(std::uint32_t entityIndex) const noexcept {
    const std::size_t page = entityIndex >> kPageShift;
    return page < pages_.size() ? pages_[page].get() : nullptr;
  }
  std::uint32_t& slot(std::uint32_t entityIndex) noexcept {
    return pages_[entityIndex >> kPageShift][entityIndex & kPageMask];
  }
  // Allocates the page holding `entityIndex` if needed.
  void ensurePage(std::uint32_t entityIndex);

  std::vector<std::unique_ptr<std::uint32_t[]>> pages_;  // null entries: untouched pages
  std::vector<Entity> dense_;
};

}  // namespace engine::ecs
