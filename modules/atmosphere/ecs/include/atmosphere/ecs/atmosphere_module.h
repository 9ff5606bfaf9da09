#pragma once
// The atmosphere's engine module. Supported when the world has an Atmosphere and a renderer has
// published its RenderDevice; installing it creates the atmosphere module on that device (a
// device that cannot run it makes the module skip itself with a warning: the scene runs with
// the renderer's own sky), registers its render feature (which draws the sky and the aerial
// perspective, and hands later features the sky's radiance and the haze), publishes the sun's
// transmittance through its air (engine::render::SunTransmittance), and keeps the scene's
// SkyLight and an AtmosphereStatus up to date from what its sky measured. Install it before
// modules whose passes read the sky (the clouds).
#include <memory>

#include "engine/ecs/module.h"

namespace atmosphere::ecs {

class AtmosphereFeature;

class AtmosphereModule final : public engine::ecs::Module {
 public:
  AtmosphereModule();
  ~AtmosphereModule() override;
  std::string_view name() const override { return "atmosphere"; }
  bool supported(const engine::ecs::World& world, std::string& reason) const override;
  void install(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) override;

 private:
  std::unique_ptr<AtmosphereFeature> feature_;
};

}  // namespace atmosphere::ecs
