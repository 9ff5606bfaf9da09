#include "engine/ecs/world.h"

namespace engine::ecs {

World::~World() {
  // Explicit so components die before event queues and singletons even if the member order
  // is ever changed: components may reference singletons (devices, allocators).
  pools_.clear();
  eventQueues_.clear();
  ctx_.clear();
}

World::World(World&& other) noexcept
    : ctx_(std::move(other.ctx_)),
      eventQueues_(std::move(other.eventQueues_)),
      pools_(std::move(other.pools_)),
      slots_(std::move(other.slots_)),
      deferred_(std::move(other.deferred_)),
      freeHead_(std::exchange(other.freeHead_, kNoFree)),
      aliveCount_(std::exchange(other.aliveCount_, 0)) {
  other.slots_.clear();
}

World& World::operator=(World&& other) noexcept {
  if (this != &other) {
    pools_.clear();
    eventQueues_.clear();
    ctx_ = std::move(other.ctx_);
    eventQueues_ = std::move(other.eventQueues_);
    pools_ = std::move(other.pools_);
    slots_ = std::move(other.slots_);
    deferred_ = std::move(other.deferred_);
    freeHead_ = std::exchange(other.freeHead_, kNoFree);
    aliveCount_ = std::exchange(other.aliveCount_, 0);
    other.eventQueues_.clear();
    other.pools_.clear();
    other.slots_.clear();
    other.deferred_.clear();
  }
  return *this;
}

Entity World::create() {
  if (freeHead_ != kNoFree) {
    const std::uint32_t index = freeHead_;
    Slot& slot = slots_[index];
    freeHead_ = slot.nextFree;
    slot.alive = true;
    ++aliveCount_;
    return Entity{index, slot.generation};
  }
  // Entity::kNullIndex is reserved for the null handle.
  if (slots_.size() >= Entity::kNullIndex) {
    detail::fail("World::create", "", "entity index space exhausted");
  }
  const auto index = static_cast<std::uint32_t>(slots_.size());
  slots_.push_back(Slot{0, kNoFree, true});
  ++aliveCount_;
  return Entity{index, 0};
}

void World::destroy(Entity entity) {
  requireAlive(entity, "World::destroy", "");
  for (const std::unique_ptr<SparseSet>& pool : pools_) {
    if (pool) pool->remove(entity);
  }
  releaseSlot(entity.index);
}

void World::clear() {
  for (const std::unique_ptr<SparseSet>& pool : pools_) {
    if (pool) pool->clear();
  }
  // Highest index first, so the free list hands out low indices first afterwards.
  for (std::size_t i = slots_.size(); i > 0; --i) {
    if (slots_[i - 1].alive) releaseSlot(static_cast<std::uint32_t>(i - 1));
  }
  deferred_.clear();
}

void World::reserveEntities(std::size_t capacity) {
  slots_.reserve(capacity);
}

void World::flushDeferred() {
  // By index: the list is not touched by destroy(), but this stays correct even if a
  // component destructor queues more.
  for (std::size_t i = 0; i < deferred_.size(); ++i) {
    const Entity entity = deferred_[i];
    if (alive(entity)) destroy(entity);
  }
  deferred_.clear();
}

void World::updateEvents() noexcept {
  for (const std::unique_ptr<EventQueueBase>& queue : eventQueues_) {
    if (queue) queue->update();
  }
}

void World::requireAlive(Entity entity, std::string_view where, std::string_view type) const {
  if (!alive(entity)) {
    detail::failEntity(where, type, entity, "is not alive (destroyed, never created or null)");
  }
}

void World::releaseSlot(std::uint32_t index) noexcept {
  Slot& slot = slots_[index];
  slot.alive = false;
  --aliveCount_;
  ++slot.generation;
  // A generation that reached the null value would make handles ambiguous: retire the slot.
  if (slot.generation == Entity::kNullGeneration) return;
  slot.nextFree = freeHead_;
  freeHead_ = index;
}

}  // namespace engine::ecs
