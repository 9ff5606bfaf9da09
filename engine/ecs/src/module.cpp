#include "engine/ecs/module.h"

#include "engine/core/log.h"

namespace engine::ecs {

Module::~Module() = default;

bool Module::supported(const World& /*world*/, std::string& /*reason*/) const { return true; }

bool installModule(Module& module, World& world, Scheduler& scheduler) {
  std::string reason;
  if (!module.supported(world, reason)) {
    std::string message = "module '";
    message += module.name();
    message += "' skipped: ";
    message += reason.empty() ? std::string("unsupported") : reason;
    engine::log::warning(message);
    return false;
  }
  module.install(world, scheduler);
  return true;
}

}  // namespace engine::ecs
