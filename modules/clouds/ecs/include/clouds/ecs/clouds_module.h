#pragma once
// The clouds' engine module: installs "clouds: frame inputs" in PreRender, which builds the
// module's per-frame inputs from the world (engine::render::Camera, Sun, SkyLight, the frame
// time, the CloudLayer's settings and the camera's CloudQuality preset). Unsupported (skipped)
// when the world has no CloudLayer.
#include "clouds/clouds.h"
#include "engine/ecs/module.h"

namespace clouds::ecs {

// What the system does, without a renderer: this frame's camera (last frame's becomes the
// previous), sun, sky and time into `inputs`, and the settings the camera renders with (the
// layer's look under the camera's CloudQuality preset, or the layer's settings as they are).
void updateFrameInputs(engine::ecs::World& world, clouds::FrameInputs& inputs,
                       clouds::Settings& settings);

class CloudsModule final : public engine::ecs::Module {
 public:
  std::string_view name() const override { return "clouds"; }
  bool supported(const engine::ecs::World& world, std::string& reason) const override;
  void install(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) override;
};

}  // namespace clouds::ecs
