// The HUD's footprint (no GPU: laid out in an ImGui context of its own): by default one line
// under a tenth of a 640x360 window, with the help and the passes' times only on F1.
#include "render/hud_layout.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <vector>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/render/scene_components.h"
#include "game/game_components.h"
#include "game/live_settings.h"
#include "render/hud_draw_plan.h"
#include "render/settings_panel.h"

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
    sample::SceneDescription scene;
    scene.clouds = sample::CloudDescription{};
    world.ctx().emplace<sample::LiveScene>(sample::LiveScene{scene, "edited.json", {}});
    // The default scene's passes.
    for (const char* name :
         {"cloud shadows", "atmosphere luts", "terrain sunlight", "scene", "sky", "clouds",
          "clouds composite", "god rays", "haze", "tonemap + overlay"}) {
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

// The settings panel (F2) fits a 640x360 window below the HUD's line: it scrolls rather than
// run off the bottom.
TEST(Hud, TheSettingsPanelFitsTheWindow) {
  HudWorld w;
  const glm::vec2 panel = sample::measureHud(w.world, w.timings, VkExtent2D{640, 360}, false, true);
  std::printf("the settings panel: %.0f x %.0f px\n", double(panel.x), double(panel.y));
  const glm::vec2 line = sample::measureHud(w.world, w.timings, VkExtent2D{640, 360}, false);
  EXPECT_GE(sample::kSettingsPanelTop, 6.0f + line.y);  // below the HUD's line
  EXPECT_LE(sample::kSettingsPanelTop + panel.y, 360.0f - 6.0f);
  EXPECT_GT(panel.y, 200.0f);  // it has its sliders
  EXPECT_LE(panel.x, 640.0f - 12.0f);
}

// Drawn, most of the panel and the HUD's line is cleared rather than blended (the backgrounds:
// hud_draw_plan.h), with the style the HUD sets: what keeps the panel within its 0.5 ms on a
// CPU device.
TEST(Hud, MostOfThePanelIsClearedNotBlended) {
  HudWorld w;
  const VkExtent2D window{640, 360};
  ImGuiContext* context = sample::createLayoutContext(window);
  const ImGuiIO& io = ImGui::GetIO();
  sample::flattenOverWindows(ImGui::GetStyle());
  glm::vec2 line{0.0f};
  glm::vec2 panel{0.0f};
  sample::HudDrawPlan plan;
  for (int frame = 0; frame < 2; ++frame) {  // auto-resizing windows take their size a frame late
    ImGui::NewFrame();
    line = sample::layOutHud(w.world, w.timings, 1.0 / 30.0, false);
    panel = sample::layOutSettingsPanel(w.world, window, true);
    ImGui::Render();
    plan = sample::planHudDraws(*ImGui::GetDrawData(), io.Fonts->TexUvWhitePixel, window);
  }
  ImGui::DestroyContext(context);
  double cleared = 0.0;
  for (const sample::HudClear& clear : plan.clears) {
    cleared += double(clear.rect.extent.width) * double(clear.rect.extent.height);
  }
  const double windows = double(line.x) * double(line.y) + double(panel.x) * double(panel.y);
  std::printf("cleared %.0f px of the windows' %.0f, in %zu clears; %zu draws\n", cleared, windows,
              plan.clears.size(), plan.draws.size());
  EXPECT_GT(cleared, 0.9 * windows);  // the window backgrounds, at least
}

}  // namespace
