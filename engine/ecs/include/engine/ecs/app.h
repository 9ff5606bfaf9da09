#pragma once
// App: a World, a Scheduler and the modules installed into them, with matching lifetimes.
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/ecs/module.h"
#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"

namespace engine::ecs {

/// Owns a World, a Scheduler and the installed modules. Destruction runs scheduler (systems
/// and their captures) first, then the world, then the modules, so systems never outlive the
/// modules they point into. Not thread-safe.
class App {
 public:
  App() = default;
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  World& world() noexcept { return world_; }
  const World& world() const noexcept { return world_; }
  Scheduler& scheduler() noexcept { return scheduler_; }
  const Scheduler& scheduler() const noexcept { return scheduler_; }

  /// Takes `module` and installs it (see installModule()). Returns true when installed; false
  /// when it was skipped as unsupported, after logging a warning (the module is then
  /// destroyed and its name listed by skippedModules()). Throws engine::Error for a null
  /// module or a name already added.
  bool addModule(std::unique_ptr<Module> module);

  /// Constructs an M from `args` and adds it.
  template <class M, class... Args>
  bool addModule(Args&&... args) {
    static_assert(std::is_base_of_v<Module, M>, "M must derive from engine::ecs::Module");
    return addModule(std::make_unique<M>(std::forward<Args>(args)...));
  }

  /// True when a module with this name is installed.
  bool hasModule(std::string_view name) const noexcept;
  /// Names of installed modules, in installation order.
  std::vector<std::string_view> installedModules() const;
  /// Names of modules skipped as unsupported, in the order they were added.
  const std::vector<std::string>& skippedModules() const noexcept { return skipped_; }

  /// scheduler().runFrame(world()). Set FrameTime in world().ctx() before, if used.
  void runFrame() { scheduler_.runFrame(world_); }

 private:
  // Declaration order matters: members are destroyed bottom-up.
  std::vector<std::unique_ptr<Module>> modules_;
  std::vector<std::string> skipped_;
  World world_;
  Scheduler scheduler_;
};

}  // namespace engine::ecs
