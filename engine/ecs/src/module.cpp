#include "engine/ecs/module.h"

#include "engine/core/log.h"

namespace engine::ecs {

Module::~Module() = default;

bool Module::supported(const World& /*world*/, std::string& /*reason*/) const {
  return true;
}

namespace {

bool skip(const Module& module, const std::string& reason) {
  std::string message = "module '";
  message += module.name();
  message += "' skipped: ";
  message += reason.empty() ? std::string("unsupported") : reason;
  engine::log::warning(message);
  return false;
}

}  // namespace

bool installModule(Module& module, World& world, Scheduler& scheduler) {
  std::string reason;
  if (!module.supported(world, reason)) return skip(module, reason);
  try {
    module.install(world, scheduler);
  } catch (const ModuleUnsupported& unsupported) {
    return skip(module, unsupported.what());
  }
  return true;
}

}  // namespace engine::ecs
