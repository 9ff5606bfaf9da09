#pragma once
// Per-frame values that one pass publishes for others, held by the frame graph and found by
// their type (Filament's blackboard, typed instead of named).
//
// An entry is put while the graph is built: the handles of what its publisher made and what
// is known then. The publishing pass updates the entry's per-frame values when it executes,
// and the passes that use them read them when they execute, after the publisher because they
// read a resource it wrote (the entry's texture). A value that changes every frame (a shadow
// map's parameters, the air's scattering) is therefore never snapshotted when the graph is
// built, and effects can exchange values the engine knows nothing of: the entry types belong
// to whoever defines the contract between them, not to the engine.
//
// Entries keep their address for the graph's life (a later put() of the same type assigns in
// place), so a pass may hold a pointer to one. Lookups do not allocate.
#include <memory>
#include <string>
#include <typeindex>
#include <typeinfo>
#include <utility>
#include <vector>

namespace engine::render {

class Blackboard {
 public:
  // Adds the entry of type T, or assigns `value` to the one there is. Returns it.
  template <typename T>
  T& put(T value) {
    if (T* existing = find<T>()) return *existing = std::move(value);
    auto entry = std::make_unique<Entry<T>>(std::move(value));
    T& stored = entry->value;
    entries_.emplace_back(std::type_index(typeid(T)), std::move(entry));
    return stored;
  }

  // The entry of type T, or null when nobody put one.
  template <typename T>
  T* find() {
    for (auto& [type, entry] : entries_) {
      if (type == std::type_index(typeid(T))) return &static_cast<Entry<T>&>(*entry).value;
    }
    return nullptr;
  }
  template <typename T>
  const T* find() const {
    return const_cast<Blackboard*>(this)->find<T>();
  }
  template <typename T>
  bool has() const {
    return find<T>() != nullptr;
  }

  // The entry of type T; throws engine::Error naming the type when there is none.
  template <typename T>
  T& get() {
    if (T* value = find<T>()) return *value;
    missing(typeid(T).name());
  }
  template <typename T>
  const T& get() const {
    return const_cast<Blackboard*>(this)->get<T>();
  }

  std::size_t size() const { return entries_.size(); }

 private:
  struct EntryBase {
    virtual ~EntryBase() = default;
  };
  template <typename T>
  struct Entry final : EntryBase {
    explicit Entry(T v) : value(std::move(v)) {}
    T value;
  };

  [[noreturn]] static void missing(const char* typeName);

  std::vector<std::pair<std::type_index, std::unique_ptr<EntryBase>>> entries_;
};

}  // namespace engine::render
