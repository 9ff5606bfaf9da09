#include "game/cloud_quality_controls.h"

#include <array>
#include <utility>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/ecs/world.h"
#include "engine/platform/input.h"

namespace sample {

using engine::platform::Key;

clouds::ecs::CloudFrameBudget playerFrameBudget(double targetMilliseconds) {
  clouds::ecs::CloudFrameBudget budget;
  budget.targetMilliseconds = targetMilliseconds;
  budget.source = clouds::ecs::FrameTimeSource::WallFrame;
  budget.judgedQuantile = 0.9;
  return budget;
}

void installCloudQualityControls(engine::ecs::Scheduler& scheduler,
                                 double frameTargetMilliseconds) {
  scheduler.add(engine::ecs::Phase::Input, "cloud quality keys",
                [frameTargetMilliseconds](engine::ecs::World& world) {
                  static constexpr std::array<std::pair<Key, clouds::Quality>, 5> kKeys = {{
                      {Key::Num1, clouds::Quality::Low},
                      {Key::Num2, clouds::Quality::Medium},
                      {Key::Num3, clouds::Quality::High},
                      {Key::Num4, clouds::Quality::Ultra},
                      {Key::Num5, clouds::Quality::Reference},
                  }};
                  const auto& input = world.ctx().get<engine::platform::InputState>();
                  std::vector<engine::ecs::Entity> cameras;
                  world.view<clouds::ecs::CloudQuality>().each(
                      [&](engine::ecs::Entity entity, clouds::ecs::CloudQuality&) {
                        cameras.push_back(entity);
                      });
                  for (const auto& [key, preset] : kKeys) {
                    if (!input.wasPressed(key)) continue;
                    for (engine::ecs::Entity camera : cameras) {
                      // The preset as it is: no knobs tuned.
                      world.get<clouds::ecs::CloudQuality>(camera) =
                          clouds::ecs::CloudQuality{preset};
                      world.remove<clouds::ecs::CloudFrameBudget>(camera);  // a fixed preset
                    }
                  }
                  if (input.wasPressed(Key::G)) {
                    for (engine::ecs::Entity camera : cameras) {
                      if (!world.remove<clouds::ecs::CloudFrameBudget>(camera)) {
                        world.emplace<clouds::ecs::CloudFrameBudget>(
                            camera, playerFrameBudget(frameTargetMilliseconds));
                      }
                    }
                  }
                });
}

}  // namespace sample
