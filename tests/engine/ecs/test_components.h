#pragma once
// Components shared by the ecs tests.
#include <memory>
#include <string>

namespace ecs_test {

struct Position {
  float x = 0.0f;
  float y = 0.0f;
};
struct Velocity {
  float dx = 0.0f;
  float dy = 0.0f;
};
struct Health {
  int points = 0;
};
struct Tag {};

/// Counts live instances so tests can check that every component is destroyed exactly once:
/// a missed destruction leaves `live` above zero, a double one drives `destroyed` above
/// `constructed`.
struct Tracked {
  static inline int live = 0;
  static inline int constructed = 0;
  static inline int destroyed = 0;
  static void reset() { live = constructed = destroyed = 0; }

  explicit Tracked(int v = 0) : value(v) { born(); }
  Tracked(const Tracked& other) : value(other.value) { born(); }
  Tracked(Tracked&& other) noexcept : value(other.value) { born(); }
  Tracked& operator=(const Tracked&) = default;
  Tracked& operator=(Tracked&&) noexcept = default;
  ~Tracked() {
    --live;
    ++destroyed;
  }

  int value;

 private:
  static void born() {
    ++live;
    ++constructed;
  }
};

/// Move-only component owning heap data and a tracked object.
struct MoveOnly {
  explicit MoveOnly(int v) : tracked(std::make_unique<Tracked>(v)) {}
  std::unique_ptr<Tracked> tracked;
};

}  // namespace ecs_test
