#pragma once
// World: the registry of entities, their components, context singletons and event queues.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/ecs/context.h"
#include "engine/ecs/entity.h"
#include "engine/ecs/errors.h"
#include "engine/ecs/events.h"
#include "engine/ecs/sparse_set.h"
#include "engine/ecs/storage.h"
#include "engine/ecs/type_info.h"
#include "engine/ecs/view.h"

namespace engine::ecs {

/// Owns entities and everything attached to them: one Storage per component type (created on
/// first use), context singletons (ctx()) and typed event queues (events<T>()).
///
/// Entities: create() recycles destroyed slots (most recently destroyed first) with their
/// generation bumped, so handles to destroyed entities are stale: alive() is false, has() and
/// tryGet() report nothing, and get()/emplace() throw engine::Error naming the component type.
/// A slot whose generation would reach Entity::kNullGeneration is retired, never reused.
///
/// Errors: misuse (stale handle, missing or duplicate component) throws engine::Error. That is
/// a programming error, not a per-frame condition: check with has()/tryGet() when absence is
/// expected.
///
/// Allocation: once pools, the entity table and the deferred list have reached their working
/// size (or after reserve()/reserveEntities()), creating and destroying entities, emplacing
/// and removing components and iterating views do not allocate.
///
/// Destruction order: components, then event queues, then context singletons (newest first).
/// Not thread-safe. Move-only; views and references stay valid across a move of the World.
class World {
 public:
  World() = default;
  ~World();
  /// Moves everything; `other` is left empty and usable.
  World(World&& other) noexcept;
  World& operator=(World&& other) noexcept;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // --- Entities ------------------------------------------------------------------------

  /// A new entity with no components. Throws engine::Error when the index space is exhausted.
  Entity create();

  /// Destroys a live entity and all its components. Throws engine::Error when `entity` is not
  /// alive. Inside View::each() only the current entity may be destroyed directly.
  void destroy(Entity entity);

  /// True when `entity` was returned by create() and has not been destroyed since.
  bool alive(Entity entity) const noexcept {
    return entity.index < slots_.size() && slots_[entity.index].alive &&
           slots_[entity.index].generation == entity.generation;
  }

  /// Number of live entities.
  std::size_t count() const noexcept { return aliveCount_; }

  /// Destroys every entity and component. Context singletons and event queues are kept;
  /// pending deferred destructions are dropped. Existing handles all become stale.
  void clear();

  /// Room for `capacity` entity slots without reallocation.
  void reserveEntities(std::size_t capacity);

  /// Queues `entity` for destruction by flushDeferred(); for destroying entities other than
  /// the current one while a view is being iterated. Handles no longer alive at flush time,
  /// and duplicates, are ignored. Scheduler::runFrame() flushes after every system.
  void destroyDeferred(Entity entity) { deferred_.push_back(entity); }

  /// Destroys the entities queued by destroyDeferred(), in queue order.
  void flushDeferred();

  /// Number of queued deferred destructions.
  std::size_t deferredCount() const noexcept { return deferred_.size(); }

  /// Room for `capacity` queued deferred destructions without reallocation.
  void reserveDeferred(std::size_t capacity) { deferred_.reserve(capacity); }

  // --- Components ----------------------------------------------------------------------

  /// Constructs a T on `entity` from `args` and returns it (reference invalidation: see
  /// Storage). Throws engine::Error when the entity is not alive or already has a T.
  template <class T, class... Args>
  T& emplace(Entity entity, Args&&... args) {
    requireAlive(entity, "World::emplace", typeName<T>());
    return storage<T>().emplace(entity, std::forward<Args>(args)...);
  }

  /// Like emplace(), but replaces an existing T with T(args...).
  template <class T, class... Args>
  T& emplaceOrReplace(Entity entity, Args&&... args) {
    requireAlive(entity, "World::emplaceOrReplace", typeName<T>());
    return storage<T>().emplaceOrReplace(entity, std::forward<Args>(args)...);
  }

  /// The T of `entity`. T may be const-qualified (get<const T> returns const T&). Throws
  /// engine::Error naming T when the entity is not alive or has no T.
  template <class T>
  T& get(Entity entity) {
    using C = std::remove_const_t<T>;
    C* component = tryGetChecked<C>(entity, "World::get");
    if (component == nullptr) detail::failEntity("World::get", typeName<C>(), entity, "has none");
    return *component;
  }
  template <class T>
  const std::remove_const_t<T>& get(Entity entity) const {
    using C = std::remove_const_t<T>;
    requireAlive(entity, "World::get", typeName<C>());
    const Storage<C>* pool = findStorage<C>();
    const C* component = pool != nullptr ? pool->tryGet(entity) : nullptr;
    if (component == nullptr) detail::failEntity("World::get", typeName<C>(), entity, "has none");
    return *component;
  }

  /// The T of `entity`, or nullptr when the entity is not alive or has no T.
  template <class T>
  T* tryGet(Entity entity) noexcept {
    Storage<std::remove_const_t<T>>* pool = findStorage<std::remove_const_t<T>>();
    return pool != nullptr && alive(entity) ? pool->tryGet(entity) : nullptr;
  }
  template <class T>
  const std::remove_const_t<T>* tryGet(Entity entity) const noexcept {
    const Storage<std::remove_const_t<T>>* pool = findStorage<std::remove_const_t<T>>();
    return pool != nullptr && alive(entity) ? pool->tryGet(entity) : nullptr;
  }

  /// True when `entity` is alive and has a T.
  template <class T>
  bool has(Entity entity) const noexcept {
    return tryGet<T>(entity) != nullptr;
  }

  /// Removes (destroys) the T of `entity`; returns false when it had none or is not alive.
  /// Inside View::each() only the current entity's components may be removed.
  template <class T>
  bool remove(Entity entity) {
    Storage<std::remove_const_t<T>>* pool = findStorage<std::remove_const_t<T>>();
    return pool != nullptr && alive(entity) && pool->remove(entity);
  }

  /// Number of entities that have a T.
  template <class T>
  std::size_t size() const noexcept {
    const Storage<std::remove_const_t<T>>* pool = findStorage<std::remove_const_t<T>>();
    return pool != nullptr ? pool->size() : 0;
  }

  /// Room for `capacity` T components without reallocation.
  template <class T>
  void reserve(std::size_t capacity) {
    storage<std::remove_const_t<T>>().reserve(capacity);
  }

  /// The storage of T, created on first use; lives as long as the World.
  template <class T>
  Storage<T>& storage() {
    static_assert(!std::is_const_v<T>, "storage<T>() takes the unqualified component type");
    const std::uint32_t id = detail::typeIndex<detail::ComponentFamily, T>();
    if (id >= pools_.size()) pools_.resize(id + 1);
    std::unique_ptr<SparseSet>& pool = pools_[id];
    if (!pool) pool = std::make_unique<Storage<T>>();
    return static_cast<Storage<T>&>(*pool);
  }

  /// The storage of T, or nullptr when no T was ever stored (never creates one).
  template <class T>
  Storage<T>* findStorage() noexcept {
    return const_cast<Storage<T>*>(std::as_const(*this).findStorage<T>());
  }
  template <class T>
  const Storage<T>* findStorage() const noexcept {
    static_assert(!std::is_const_v<T>, "findStorage<T>() takes the unqualified component type");
    const std::uint32_t id = detail::typeIndex<detail::ComponentFamily, T>();
    if (id >= pools_.size() || !pools_[id]) return nullptr;
    return static_cast<const Storage<T>*>(pools_[id].get());
  }

  /// A view of the entities that have all of Ts (`const T` for read-only access). Creates
  /// missing storages, so it may allocate the first time a type is seen, never afterwards.
  template <class... Ts>
  View<Ts...> view() {
    return View<Ts...>(storage<std::remove_const_t<Ts>>()...);
  }

  // --- Context singletons and events -------------------------------------------------------

  /// The World's singletons (frame time, settings, services). See Context.
  Context& ctx() noexcept { return ctx_; }
  const Context& ctx() const noexcept { return ctx_; }

  /// The queue of T events, created on first use; lives as long as the World.
  template <class T>
  EventQueue<T>& events() {
    static_assert(!std::is_const_v<T>, "events<T>() takes the unqualified event type");
    const std::uint32_t id = detail::typeIndex<detail::EventFamily, T>();
    if (id >= eventQueues_.size()) eventQueues_.resize(id + 1);
    std::unique_ptr<EventQueueBase>& queue = eventQueues_[id];
    if (!queue) queue = std::make_unique<EventQueue<T>>();
    return static_cast<EventQueue<T>&>(*queue);
  }

  /// The queue of T events, or nullptr when none was ever created.
  template <class T>
  const EventQueue<T>* findEvents() const noexcept {
    const std::uint32_t id = detail::typeIndex<detail::EventFamily, T>();
    if (id >= eventQueues_.size() || !eventQueues_[id]) return nullptr;
    return static_cast<const EventQueue<T>*>(eventQueues_[id].get());
  }

  /// Calls update() on every event queue (advances the double buffers by one frame).
  /// Scheduler::runFrame() calls it once at the end of each frame.
  void updateEvents() noexcept;

 private:
  struct Slot {
    std::uint32_t generation = 0;
    std::uint32_t nextFree = 0;  // next slot in the free list while !alive
    bool alive = false;
  };

  // Throws engine::Error "<where><type>: entity {...} is not alive" unless alive(entity).
  void requireAlive(Entity entity, std::string_view where, std::string_view type) const;
  // Retires the slot of a just-destroyed entity: bumps the generation, links the free list.
  void releaseSlot(std::uint32_t index) noexcept;

  template <class C>
  C* tryGetChecked(Entity entity, std::string_view where) {
    requireAlive(entity, where, typeName<C>());
    Storage<C>* pool = findStorage<C>();
    return pool != nullptr ? pool->tryGet(entity) : nullptr;
  }

  // Declaration order is destruction order reversed: components go first, singletons last.
  Context ctx_;
  std::vector<std::unique_ptr<EventQueueBase>> eventQueues_;  // by EventFamily id, may be null
  std::vector<std::unique_ptr<SparseSet>> pools_;             // by ComponentFamily id
  std::vector<Slot> slots_;
  std::vector<Entity> deferred_;
  std::uint32_t freeHead_ = kNoFree;
  std::size_t aliveCount_ = 0;

  static constexpr std::uint32_t kNoFree = UINT32_MAX;
};

}  // namespace engine::ecs
