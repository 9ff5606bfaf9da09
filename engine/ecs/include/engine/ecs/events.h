#pragma once
// Typed event queues with Bevy-style double buffering, and per-reader cursors.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/ecs/construct.h"

namespace engine::ecs {

/// Type-erased face of an EventQueue, so a World can advance all of its queues each frame.
class EventQueueBase {
 public:
  EventQueueBase() = default;
  virtual ~EventQueueBase();
  EventQueueBase(const EventQueueBase&) = delete;
  EventQueueBase& operator=(const EventQueueBase&) = delete;

  /// Advances one frame: drops the events sent before the previous update() and keeps the
  /// ones sent since, so every event is readable during the frame it was sent and the next.
  virtual void update() noexcept = 0;
  /// Drops every stored event now. Readers' cursors stay valid (they count these as missed).
  virtual void clear() noexcept = 0;
};

template <class T>
class EventReader;

/// Events not yet seen by one reader, oldest first: a view of up to two contiguous runs.
/// Invalidation: valid until the next send(), update() or clear() on the queue it came from.
template <class T>
class EventRange {
 public:
  class Iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = const T*;
    using reference = const T&;

    Iterator() = default;
    const T& operator*() const noexcept { return *current_; }
    const T* operator->() const noexcept { return current_; }
    Iterator& operator++() noexcept {
      ++current_;
      if (current_ == firstEnd_) {
        // Hop from the older run to the newer one.
        current_ = second_.data();
        firstEnd_ = nullptr;
      }
      return *this;
    }
    Iterator operator++(int) noexcept {
      Iterator old = *this;
      ++*this;
      return old;
    }
    friend bool operator==(const Iterator& a, const Iterator& b) noexcept {
      return a.current_ == b.current_;
    }

   private:
    friend class EventRange;
    Iterator(const T* current, const T* firstEnd, std::span<const T> second) noexcept
        : current_(current), firstEnd_(firstEnd), second_(second) {}
    const T* current_ = nullptr;
    const T* firstEnd_ = nullptr;
    std::span<const T> second_;
  };

  EventRange() = default;
  EventRange(std::span<const T> older, std::span<const T> newer) noexcept
      : older_(older), newer_(newer) {}

  Iterator begin() const noexcept {
    if (older_.empty()) return Iterator(newer_.data(), nullptr, {});
    return Iterator(older_.data(), older_.data() + older_.size(), newer_);
  }
  Iterator end() const noexcept {
    // The pointer the last increment produces: one past the newer run, or its start when the
    // newer run is empty (the hop from the older run lands there).
    return Iterator(newer_.data() + newer_.size(), nullptr, {});
  }
  std::size_t size() const noexcept { return older_.size() + newer_.size(); }
  bool empty() const noexcept { return size() == 0; }
  /// Element `i` in oldest-first order. Precondition: i < size().
  const T& operator[](std::size_t i) const noexcept {
    return i < older_.size() ? older_[i] : newer_[i - older_.size()];
  }

 private:
  std::span<const T> older_;
  std::span<const T> newer_;
};

/// A queue of T events, double buffered. send() appends to the current frame's buffer;
/// update(), called once per frame (Scheduler::runFrame does it for every queue of the World),
/// discards the previous frame's buffer and starts a new one. An event is therefore readable
/// during the frame it is sent and the whole next frame, whatever the order of the sending and
/// reading systems, and is then dropped.
///
/// Ownership: the queue owns its events; readers only hold a cursor. Both buffers keep their
/// capacity, so a warm queue sends and updates without allocating. Not thread-safe.
template <class T>
class EventQueue final : public EventQueueBase {
  static_assert(std::is_object_v<T> && !std::is_const_v<T>, "events must be non-const objects");

 public:
  EventQueue() = default;

  void send(const T& event) {
    newer_.push_back(event);
    ++sent_;
  }
  void send(T&& event) {
    newer_.push_back(std::move(event));
    ++sent_;
  }
  /// Constructs the event in place from `args`.
  template <class... Args>
  T& emplace(Args&&... args) {
    T& event = detail::emplaceBack<T>(newer_, std::forward<Args>(args)...);
    ++sent_;
    return event;
  }

  void update() noexcept override {
    // The newer buffer becomes the older one; the old older buffer is emptied and reused, so
    // both keep their capacity.
    std::swap(older_, newer_);
    newer_.clear();
    olderStart_ = newerStart_;
    newerStart_ = sent_;
  }

  void clear() noexcept override {
    older_.clear();
    newer_.clear();
    olderStart_ = sent_;
    newerStart_ = sent_;
  }

  /// Events currently stored (this frame's and last frame's).
  std::size_t size() const noexcept { return older_.size() + newer_.size(); }
  bool empty() const noexcept { return size() == 0; }
  /// Events ever sent to this queue; a reader's cursor is a position in this sequence.
  std::uint64_t sentCount() const noexcept { return sent_; }

  /// Every stored event, oldest first, regardless of readers.
  EventRange<T> all() const noexcept { return EventRange<T>(older_, newer_); }

  /// Makes room for `perFrame` events in each buffer, so sending that many per frame never
  /// allocates even in the first frames.
  void reserve(std::size_t perFrame) {
    older_.reserve(perFrame);
    newer_.reserve(perFrame);
  }

 private:
  friend class EventReader<T>;

  std::vector<T> older_;          // sent during the previous frame
  std::vector<T> newer_;          // sent during this frame
  std::uint64_t olderStart_ = 0;  // sequence number of older_[0]
  std::uint64_t newerStart_ = 0;  // sequence number of newer_[0]
  std::uint64_t sent_ = 0;
};

/// A cursor into an EventQueue<T>'s sequence: each read() returns the events this reader has
/// not returned before, so two readers see the same events independently and one reader never
/// sees an event twice. A default reader starts at the beginning (it sees everything still
/// stored); EventReader(queue) starts at the end (only events sent from now on).
/// A plain value (no allocation, no reference to the queue): keep one per consuming system.
template <class T>
class EventReader {
 public:
  EventReader() = default;
  explicit EventReader(const EventQueue<T>& queue) noexcept : cursor_(queue.sent_) {}

  /// The unread events, oldest first; marks them read. See EventRange for invalidation.
  EventRange<T> read(const EventQueue<T>& queue) noexcept {
    // Events older than the older buffer were dropped before this reader got to them.
    if (cursor_ < queue.olderStart_) {
      missed_ += queue.olderStart_ - cursor_;
      cursor_ = queue.olderStart_;
    }
    const std::span<const T> older = unreadPart(queue.older_, queue.olderStart_);
    const std::span<const T> newer = unreadPart(queue.newer_, queue.newerStart_);
    cursor_ = queue.sent_;
    return EventRange<T>(older, newer);
  }

  /// Number of events read() would return now.
  std::size_t unreadCount(const EventQueue<T>& queue) const noexcept {
    const std::uint64_t from = std::max(cursor_, queue.olderStart_);
    return static_cast<std::size_t>(queue.sent_ - from);
  }

  /// Marks everything sent so far as read.
  void skipAll(const EventQueue<T>& queue) noexcept { cursor_ = queue.sent_; }

  /// Events that were dropped before this reader read them (it read too rarely).
  std::uint64_t missedCount() const noexcept { return missed_; }

 private:
  std::span<const T> unreadPart(const std::vector<T>& buffer, std::uint64_t start) const noexcept {
    const std::uint64_t skip = cursor_ > start ? cursor_ - start : 0;
    const auto skipped = static_cast<std::size_t>(std::min<std::uint64_t>(skip, buffer.size()));
    return std::span<const T>(buffer).subspan(skipped);
  }

  std::uint64_t cursor_ = 0;
  std::uint64_t missed_ = 0;
};

}  // namespace engine::ecs
