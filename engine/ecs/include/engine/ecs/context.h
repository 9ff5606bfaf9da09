#pragma once
// Context singletons: at most one instance per type, owned by the World.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/ecs/construct.h"
#include "engine/ecs/errors.h"
#include "engine/ecs/type_info.h"

namespace engine::ecs {

/// Per-World singletons ("resources" in Bevy): frame time, settings, device handles, input
/// state. Holds at most one instance of each type and owns it; instances are destroyed in
/// reverse order of emplacement when the Context dies.
///
/// Invalidation: a reference stays valid until that type is erased or replaced
/// (emplaceOrReplace assigns in place, so it stays valid there too) or the Context dies;
/// emplacing other types never moves existing instances. Not thread-safe.
class Context {
 public:
  Context() = default;
  ~Context();
  Context(Context&&) noexcept = default;
  /// Destroys this context's singletons (newest first), then takes over `other`'s.
  Context& operator=(Context&& other) noexcept;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  /// Constructs the T singleton from `args`. Throws engine::Error naming T when present.
  template <class T, class... Args>
  T& emplace(Args&&... args) {
    checkType<T>();
    const std::uint32_t id = detail::typeIndex<detail::ContextFamily, T>();
    if (id < entries_.size() && entries_[id]) {
      detail::fail("Context::emplace", typeName<T>(), "already present");
    }
    if (id >= entries_.size()) entries_.resize(id + 1);
    order_.reserve(order_.size() + 1);  // so recording the order below cannot throw
    auto holder = std::make_unique<Holder<T>>(std::forward<Args>(args)...);
    T& value = holder->value;
    entries_[id] = std::move(holder);
    order_.push_back(id);
    return value;
  }

  /// Like emplace(), but assigns T(args...) to an existing instance instead of failing.
  template <class T, class... Args>
  T& emplaceOrReplace(Args&&... args) {
    if (T* existing = tryGet<T>()) {
      *existing = detail::construct<T>(std::forward<Args>(args)...);
      return *existing;
    }
    return emplace<T>(std::forward<Args>(args)...);
  }

  /// The T singleton; throws engine::Error naming T when absent.
  template <class T>
  T& get() {
    T* value = tryGet<T>();
    if (value == nullptr) detail::fail("Context::get", typeName<T>(), "not present");
    return *value;
  }
  template <class T>
  const T& get() const {
    const T* value = tryGet<T>();
    if (value == nullptr) detail::fail("Context::get", typeName<T>(), "not present");
    return *value;
  }

  /// The T singleton, or nullptr when absent.
  template <class T>
  T* tryGet() noexcept {
    return const_cast<T*>(std::as_const(*this).tryGet<T>());
  }
  template <class T>
  const T* tryGet() const noexcept {
    checkType<T>();
    const std::uint32_t id = detail::typeIndex<detail::ContextFamily, T>();
    if (id >= entries_.size() || !entries_[id]) return nullptr;
    return &static_cast<const Holder<T>&>(*entries_[id]).value;
  }

  template <class T>
  bool has() const noexcept {
    return tryGet<T>() != nullptr;
  }

  /// Destroys the T singleton; returns false when there was none.
  template <class T>
  bool erase() {
    checkType<T>();
    const std::uint32_t id = detail::typeIndex<detail::ContextFamily, T>();
    if (id >= entries_.size() || !entries_[id]) return false;
    eraseId(id);
    return true;
  }

  /// Number of singletons held.
  std::size_t size() const noexcept { return order_.size(); }

  /// Destroys every singleton, newest first.
  void clear() noexcept;

 private:
  struct Entry {
    virtual ~Entry() = default;
  };
  template <class T>
  struct Holder final : Entry {
    template <class... Args>
    explicit Holder(Args&&... args) : value(detail::construct<T>(std::forward<Args>(args)...)) {}
    T value;
  };

  template <class T>
  static constexpr void checkType() noexcept {
    static_assert(std::is_object_v<T> && !std::is_const_v<T> && !std::is_volatile_v<T>,
                  "context singletons must be non-const, non-volatile object types");
  }
  void eraseId(std::uint32_t id) noexcept;

  std::vector<std::unique_ptr<Entry>> entries_;  // indexed by ContextFamily type id
  std::vector<std::uint32_t> order_;             // ids in emplacement order
};

}  // namespace engine::ecs
