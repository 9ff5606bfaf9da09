#include "engine/ecs/sparse_set.h"

#include <algorithm>

#include "engine/ecs/errors.h"

namespace engine::ecs {

SparseSet::~SparseSet() = default;

std::size_t SparseSet::pageCount() const noexcept {
  return static_cast<std::size_t>(std::count_if(pages_.begin(), pages_.end(),
                                                [](const auto& page) { return page != nullptr; }));
}

void SparseSet::insert(Entity entity) {
  if (entity.isNull()) detail::failEntity("SparseSet::insert", "", entity, "is null");
  if (contains(entity)) detail::failEntity("SparseSet::insert", "", entity, "is already present");
  pushBack(entity);
}

bool SparseSet::remove(Entity entity) {
  if (!contains(entity)) return false;
  const std::uint32_t position = slot(entity.index);
  // Payload first: if moving the payload throws, the index structure is still consistent.
  swapAndPopPayload(position);
  const Entity moved = dense_.back();
  dense_[position] = moved;
  slot(moved.index) = position;
  // After the moved entity's slot: when the removed entity was the last one, moved == entity
  // and its slot must end up absent.
  slot(entity.index) = kAbsent;
  dense_.pop_back();
  return true;
}

void SparseSet::clear() noexcept {
  for (const Entity entity : dense_) slot(entity.index) = kAbsent;
  clearPayload();
  dense_.clear();
}

void SparseSet::reserve(std::size_t capacity) {
  dense_.reserve(capacity);
}

void SparseSet::pushBack(Entity entity) {
  ensurePage(entity.index);
  // Only one generation of an index can be alive; another one here means a stale handle.
  if (slot(entity.index) != kAbsent) {
    detail::failEntity("SparseSet::insert", "", entity, "shares its index with a present entity");
  }
  dense_.push_back(entity);  // may throw; the slot is only written once this succeeded
  slot(entity.index) = static_cast<std::uint32_t>(dense_.size() - 1);
}

void SparseSet::popBack() noexcept {
  slot(dense_.back().index) = kAbsent;
  dense_.pop_back();
}

void SparseSet::swapAndPopPayload(std::size_t /*position*/) {}

void SparseSet::clearPayload() noexcept {}

void SparseSet::ensurePage(std::uint32_t entityIndex) {
  const std::size_t page = entityIndex >> kPageShift;
  if (page >= pages_.size()) pages_.resize(page + 1);
  if (!pages_[page]) {
    auto fresh = std::make_unique<std::uint32_t[]>(kPageSize);
    std::fill_n(fresh.get(), kPageSize, kAbsent);
    pages_[page] = std::move(fresh);
  }
}

}  // namespace engine::ecs
