#include "atmosphere/ecs/atmosphere_module.h"

#include "atmosphere/ecs/atmosphere_components.h"
#include "atmosphere_feature.h"
#include "engine/ecs/world.h"
#include "engine/render/render_feature.h"

namespace atmosphere::ecs {

AtmosphereModule::AtmosphereModule() = default;
AtmosphereModule::~AtmosphereModule() = default;

bool AtmosphereModule::supported(const engine::ecs::World& world, std::string& reason) const {
  const auto* atmospheres = world.findStorage<Atmosphere>();
  if (atmospheres == nullptr || atmospheres->size() == 0) {
    reason = "the scene has no atmosphere";
    return false;
  }
  return engine::render::usableRenderDevice(world.ctx().tryGet<engine::render::RenderDevice>(),
                                            reason);
}

void AtmosphereModule::install(engine::ecs::World& world, engine::ecs::Scheduler& /*scheduler*/) {
  // Creating the feature may throw ModuleUnsupported: then nothing is registered.
  feature_ =
      std::make_unique<AtmosphereFeature>(world, world.ctx().get<engine::render::RenderDevice>());
  world.ctx().emplaceOrReplace<AtmosphereStatus>();
  if (!world.ctx().has<engine::render::RenderFeatures>()) {
    world.ctx().emplace<engine::render::RenderFeatures>();
  }
  world.ctx().get<engine::render::RenderFeatures>().features.push_back(feature_.get());
}

}  // namespace atmosphere::ecs
