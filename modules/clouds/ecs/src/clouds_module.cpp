#include "clouds/ecs/clouds_module.h"

#include "cloud_feature.h"
#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "clouds/ecs/lightning.h"
#include "engine/ecs/world.h"
#include "engine/render/render_feature.h"

namespace clouds::ecs {

CloudsModule::CloudsModule() = default;
CloudsModule::~CloudsModule() = default;

bool CloudsModule::supported(const engine::ecs::World& world, std::string& reason) const {
  const auto* layers = world.findStorage<CloudLayer>();
  if (layers == nullptr || layers->size() == 0) {
    reason = "the scene has no cloud layer";
    return false;
  }
  return engine::render::usableRenderDevice(world.ctx().tryGet<engine::render::RenderDevice>(),
                                            reason);
}

void CloudsModule::install(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) {
  const CloudLayer* layer = nullptr;
  world.view<const CloudLayer>().each([&](const CloudLayer& l) { layer = &l; });
  // Creating the feature may throw ModuleUnsupported: then nothing is registered.
  feature_ = std::make_unique<CloudFeature>(world, world.ctx().get<engine::render::RenderDevice>(),
                                            *layer);
  world.ctx().emplaceOrReplace<CloudStatus>();
  if (!world.ctx().has<engine::render::RenderFeatures>()) {
    world.ctx().emplace<engine::render::RenderFeatures>();
  }
  world.ctx().get<engine::render::RenderFeatures>().features.push_back(feature_.get());
  // Only a scene with a storm gets the lightning system.
  installLightning(world, scheduler);
  // A camera may be given a frame budget at any time (the sample's key G): a view a frame.
  installFrameBudget(world, scheduler);
}

}  // namespace clouds::ecs
