#pragma once
// The clouds' engine module: installs "clouds: frame inputs" in PreRender, which builds the
// module's per-frame inputs from the world (engine::render::Camera, Sun, SkyLight, the frame
// time and the CloudLayer's settings). Unsupported (skipped) when the world has no CloudLayer.
#include "engine/ecs/module.h"

namespace clouds::ecs {

class CloudsModule final : public engine::ecs::Module {
 public:
  std::string_view name() const override { return "clouds"; }
  bool supported(const engine::ecs::World& world, std::string& reason) const override;
  void install(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) override;
};

}  // namespace clouds::ecs
