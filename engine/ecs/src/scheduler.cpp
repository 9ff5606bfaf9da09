#include "engine/ecs/scheduler.h"

#include "engine/ecs/errors.h"
#include "engine/ecs/world.h"

namespace engine::ecs {

void Scheduler::add(Phase phase, std::string name, SystemFn system) {
  // Adding during a frame could reallocate the vector whose element is executing.
  if (inFrame_) {
    detail::fail("Scheduler::add", "", "cannot add system '" + name + "' while a frame runs");
  }
  if (name.empty()) detail::fail("Scheduler::add", "", "system name is empty");
  if (!system) detail::fail("Scheduler::add", "", "system '" + name + "' has no callable");
  if (contains(name)) detail::fail("Scheduler::add", "", "system '" + name + "' already exists");
  phases_[static_cast<std::size_t>(phase)].push_back(System{std::move(name), std::move(system)});
}

void Scheduler::runFrame(World& world) {
  if (inFrame_) detail::fail("Scheduler::runFrame", "", "re-entered from a system");
  // Resets the running state also when a system throws.
  struct FrameGuard {
    Scheduler& scheduler;
    ~FrameGuard() {
      scheduler.inFrame_ = false;
      scheduler.running_ = nullptr;
    }
  } guard{*this};
  inFrame_ = true;
  for (const std::vector<System>& phase : phases_) {
    for (const System& system : phase) {
      running_ = &system;
      system.fn(world);
      world.flushDeferred();
    }
  }
  running_ = nullptr;
  world.updateEvents();
}

std::vector<std::string> Scheduler::systemNames(Phase phase) const {
  std::vector<std::string> names;
  for (const System& system : phases_[static_cast<std::size_t>(phase)]) {
    names.push_back(system.name);
  }
  return names;
}

std::string Scheduler::describe() const {
  std::string text;
  for (const Phase phase : kAllPhases) {
    text += phaseName(phase);
    text += ':';
    const char* separator = " ";
    for (const System& system : phases_[static_cast<std::size_t>(phase)]) {
      text += separator;
      text += system.name;
      separator = ", ";
    }
    text += '\n';
  }
  return text;
}

std::size_t Scheduler::systemCount() const noexcept {
  std::size_t total = 0;
  for (const std::vector<System>& phase : phases_) total += phase.size();
  return total;
}

std::size_t Scheduler::systemCount(Phase phase) const noexcept {
  return phases_[static_cast<std::size_t>(phase)].size();
}

bool Scheduler::contains(std::string_view name) const noexcept {
  for (const std::vector<System>& phase : phases_) {
    for (const System& system : phase) {
      if (system.name == name) return true;
    }
  }
  return false;
}

std::string_view Scheduler::currentSystem() const noexcept {
  return running_ != nullptr ? std::string_view(running_->name) : std::string_view();
}

}  // namespace engine::ecs
