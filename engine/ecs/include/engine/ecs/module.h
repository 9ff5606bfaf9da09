#pragma once
// Modules: a feature packaged as singletons and systems, installed into a World + Scheduler.
#include <string>
#include <string_view>

#include "engine/core/error.h"

namespace engine::ecs {

class World;
class Scheduler;

/// A feature (an effect, camera control, debug overlay...) that installs itself: it emplaces the
/// context singletons and event queues it owns and adds its systems to the phases they belong
/// in. Modules talk to each other only through components, singletons and events.
///
/// A module whose requirements are missing (a device feature, a singleton another module
/// should have provided) reports it from supported(); installModule() then logs a warning and
/// skips it instead of failing, so the rest of the app still runs. What only installing can
/// find out (the GPU cannot create the module's objects) install() reports by throwing
/// ModuleUnsupported before it registers anything: the module is then skipped the same way.
///
/// Ownership: systems often capture `this`, so the module must outlive the Scheduler it was
/// installed into (App guarantees that).
class Module {
 public:
  virtual ~Module();

  /// Short unique name for logs and App::hasModule(), e.g. "flight".
  virtual std::string_view name() const = 0;

  /// Whether the module can run with what `world` provides. When it returns false it should
  /// set `reason` to a human-readable explanation. Defaults to true.
  virtual bool supported(const World& world, std::string& reason) const;

  /// Registers singletons, event queues and systems. Called at most once, only when
  /// supported() returned true. May throw ModuleUnsupported before registering anything, or
  /// engine::Error; installation is not transactional.
  virtual void install(World& world, Scheduler& scheduler) = 0;

 protected:
  Module() = default;
  Module(const Module&) = default;
  Module& operator=(const Module&) = default;
};

/// Thrown by Module::install() when the module cannot run here after all; `what()` is the reason.
class ModuleUnsupported : public Error {
 public:
  using Error::Error;
};

/// Installs `module` if module.supported(world) holds and its install() does not throw
/// ModuleUnsupported, and returns true; otherwise logs "module '<name>' skipped: <reason>" as
/// a warning (engine::log) and returns false.
bool installModule(Module& module, World& world, Scheduler& scheduler);

}  // namespace engine::ecs
