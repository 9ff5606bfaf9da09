#pragma once
// Scheduler: named systems grouped in fixed phases, run once per frame.
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/ecs/phase.h"

namespace engine::ecs {

class World;

/// A system: a callable run once per frame with the World. Captured state lives as long as the
/// Scheduler. Calling it does not allocate (std::function only allocates when constructed).
using SystemFn = std::function<void(World&)>;

/// Runs systems phase by phase (Phase order); within a phase, in the order they were added.
///
/// runFrame(world), per frame:
///  1. for each phase, for each system: call it, then world.flushDeferred() so deferred
///     destructions take effect before the next system runs;
///  2. world.updateEvents(), advancing every event queue's double buffer by one frame.
/// Once the systems' own work is warm, runFrame() does not allocate.
///
/// Systems must not add systems (add() throws while a frame runs). If a system throws, the
/// exception propagates, the rest of the frame is skipped and event queues are not advanced.
/// Not thread-safe.
class Scheduler {
 public:
  Scheduler() = default;
  Scheduler(Scheduler&&) noexcept = default;
  Scheduler& operator=(Scheduler&&) noexcept = default;
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;

  /// Appends `system` to `phase`. Throws engine::Error when `name` is empty or already used in
  /// any phase, when `system` is empty, or when called while runFrame() is running.
  void add(Phase phase, std::string name, SystemFn system);

  /// Runs one frame of `world`; see the class comment. Throws engine::Error when re-entered.
  void runFrame(World& world);

  /// Names of the systems of `phase`, in run order (allocates; for tests and debug output).
  std::vector<std::string> systemNames(Phase phase) const;
  /// "Input: a, b\nSimulate: c\n..." for every phase, for logs.
  std::string describe() const;

  std::size_t systemCount() const noexcept;
  std::size_t systemCount(Phase phase) const noexcept;
  /// True when a system with this name was added.
  bool contains(std::string_view name) const noexcept;
  /// Name of the system running now, or empty outside runFrame() (for error reports).
  std::string_view currentSystem() const noexcept;

 private:
  struct System {
    std::string name;
    SystemFn fn;
  };

  std::array<std::vector<System>, kPhaseCount> phases_;
  const System* running_ = nullptr;
  bool inFrame_ = false;
};

}  // namespace engine::ecs
