#pragma once
// The clouds' engine module. Supported when the world has a CloudLayer and a renderer has
// published its RenderDevice; installing it creates the clouds module on that device (a
// device that cannot run it makes the module skip itself with a warning: the scene runs
// without clouds), registers its render feature and keeps a CloudStatus singleton up to date.
// The per-frame inputs are built from the world when the "clouds" pass executes
// (cloud_frame.h): nothing else writes them.
#include <memory>

#include "clouds/clouds.h"
#include "engine/ecs/module.h"

namespace clouds::ecs {

class CloudFeature;

class CloudsModule final : public engine::ecs::Module {
 public:
  CloudsModule();
  ~CloudsModule() override;
  std::string_view name() const override { return "clouds"; }
  bool supported(const engine::ecs::World& world, std::string& reason) const override;
  void install(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) override;

 private:
  std::unique_ptr<CloudFeature> feature_;
};

}  // namespace clouds::ecs
