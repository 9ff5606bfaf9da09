#include "game/cloud_quality_controls.h"

#include <array>
#include <utility>

#include "clouds/ecs/cloud_components.h"
#include "engine/ecs/world.h"
#include "engine/platform/input.h"

namespace sample {

using engine::platform::Key;

void installCloudQualityControls(engine::ecs::Scheduler& scheduler) {
  scheduler.add(engine::ecs::Phase::Input, "cloud quality keys", [](engine::ecs::World& world) {
    static constexpr std::array<std::pair<Key, clouds::Quality>, 5> kKeys = {{
        {Key::Num1, clouds::Quality::Low},
        {Key::Num2, clouds::Quality::Medium},
        {Key::Num3, clouds::Quality::High},
        {Key::Num4, clouds::Quality::Ultra},
        {Key::Num5, clouds::Quality::Reference},
    }};
    const auto& input = world.ctx().get<engine::platform::InputState>();
    for (const auto& [key, preset] : kKeys) {
      if (!input.wasPressed(key)) continue;
      world.view<clouds::ecs::CloudQuality>().each(
          [&](clouds::ecs::CloudQuality& quality) { quality.preset = preset; });
    }
  });
}

}  // namespace sample
