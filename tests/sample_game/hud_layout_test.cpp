// The HUD's footprint (no GPU: laid out in an ImGui context of its own): by default one line
// under a tenth of a 640x360 window, with the help and the passes' times only on F1.
#include "render/hud_layout.h"

#include <gtest/gtest.h>

#include <vector>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/render/scene_components.h"
#include "game/game_components.h"

namespace {

struct HudWorld {
  engine::ecs::World world;
  std::vector<engine::gfx::TimedScope> timings;
  HudWorld() {
    const engine::ecs::Entity camera = world.create();
    world.emplace<engine::render::Camera>(camera, engine::render::Camera{});
    world.emplace<sample::Aircraft>(camera, sample::Aircraft{});
    world.emplace<clouds::ecs::CloudQuality>(camera, clouds::ecs::CloudQuality{});
    clouds::ecs::CloudGovernorStatus governor;
    governor.active = true;
    governor.targetMilliseconds = 33.3;
    governor.reason = "holding";
    world.ctx().emplace<clouds::ecs::CloudGovernorStatus>(governor);
    world.ctx().emplace<clouds::ecs::CloudStatus>();
    // The default scene's passes.
    for (const char* name : {"cloud shadows", "atmosphere luts", "terrain sunlight", "scene", "sky",
                             "clouds", "clouds composite", "god rays", "haze", "tonemap", "hud"}) {
      timings.push_back(engine::gfx::TimedScope{name, 1.25});
    }
  }
};

TEST(Hud, ByDefaultItIsOneLineUnderATenthOfTheWindow) {
  HudWorld w;
  const VkExtent2D window{640, 360};
  const glm::vec2 line = sample::measureHud(w.world, w.timings, window, false);
  const double share = double(line.x) * double(line.y) / (640.0 * 360.0);
  std::printf("the HUD: %.0f x %.0f px, %.1f%% of 640x360\n", double(line.x), double(line.y),
              100.0 * share);
  EXPECT_LT(share, 0.10);
  EXPECT_LT(line.y, 40.0f);  // one line of text
  EXPECT_LT(line.x, 640.0f);

  // F1: the help and every pass's time.
  const glm::vec2 full = sample::measureHud(w.world, w.timings, window, true);
  EXPECT_GT(full.y, line.y + 14.0f * float(w.timings.size()));
}

}  // namespace
