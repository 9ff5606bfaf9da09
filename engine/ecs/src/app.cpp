#include "engine/ecs/app.h"

#include <algorithm>

#include "engine/ecs/errors.h"

namespace engine::ecs {

App::~App() = default;

bool App::addModule(std::unique_ptr<Module> module) {
  if (!module) detail::fail("App::addModule", "", "module is null");
  const std::string_view name = module->name();
  if (hasModule(name) || std::find(skipped_.begin(), skipped_.end(), name) != skipped_.end()) {
    detail::fail("App::addModule", "",
                 "a module named '" + std::string(name) + "' was already added");
  }
  // Owned before install() runs: if it throws halfway, systems it already added may point
  // into it, so it must live as long as the scheduler.
  modules_.push_back(std::move(module));
  if (!installModule(*modules_.back(), world_, scheduler_)) {
    skipped_.emplace_back(modules_.back()->name());
    modules_.pop_back();
    return false;
  }
  return true;
}

bool App::hasModule(std::string_view name) const noexcept {
  return std::any_of(modules_.begin(), modules_.end(),
                     [name](const auto& module) { return module->name() == name; });
}

std::vector<std::string_view> App::installedModules() const {
  std::vector<std::string_view> names;
  names.reserve(modules_.size());
  for (const std::unique_ptr<Module>& module : modules_) names.push_back(module->name());
  return names;
}

}  // namespace engine::ecs
