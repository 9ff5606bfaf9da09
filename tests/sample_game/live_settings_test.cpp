// The live settings (what the settings panel and a script's "set" change): each writes the
// world and the scene that a save writes alike, refuses what is out of range or absent by name,
// and the scene to save folds in the camera's preset and budget.
#include "game/live_settings.h"
#include "game/scene_hot_reload.h"

#include <gtest/gtest.h>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/frame_budget.h"
#include "engine/core/error.h"
#include "engine/render/exposure.h"
#include "engine/render/scene_components.h"
#include "game/game_components.h"

namespace {

struct LiveWorld {
  engine::ecs::World world;
  engine::ecs::Entity camera;
  explicit LiveWorld(bool withClouds = true) {
    sample::SceneDescription scene;
    if (withClouds) {
      scene.clouds = sample::CloudDescription{};
      world.emplace<clouds::ecs::CloudLayer>(world.create(), clouds::ecs::CloudLayer{});
    }
    world.emplace<sample::TimeOfDay>(world.create(), sample::TimeOfDay{});
    world.ctx().emplace<engine::render::Exposure>();
    camera = world.create();
    world.emplace<engine::render::Camera>(camera, engine::render::Camera{});
    world.emplace<clouds::ecs::CloudQuality>(camera, clouds::ecs::CloudQuality{});
    world.ctx().emplace<sample::LiveScene>(sample::LiveScene{scene, "unused.json", {}});
  }
  const sample::SceneDescription& scene() { return world.ctx().get<sample::LiveScene>().scene; }
  clouds::Settings layer() {
    clouds::Settings settings;
    world.view<const clouds::ecs::CloudLayer>().each(
        [&](const clouds::ecs::CloudLayer& l) { settings = l.settings; });
    return settings;
  }
};

std::string refusal(engine::ecs::World& world, const char* name, double value) {
  try {
    sample::applyLiveSetting(world, name, value);
  } catch (const engine::Error& error) {
    return error.what();
  }
  return "";
}

TEST(LiveSettings, EachWritesTheWorldAndTheSceneToSave) {
  for (const sample::LiveSetting& setting : sample::liveSettings()) {
    LiveWorld w;
    SCOPED_TRACE(setting.name);
    const double value = setting.min + 0.375 * (setting.max - setting.min);
    ASSERT_TRUE(setting.available(w.scene()));
    sample::applyLiveSetting(w.world, setting.name, value);
    EXPECT_NEAR(setting.get(w.scene()), value, 1e-5 * (1.0 + std::abs(value)));
  }
  LiveWorld w;
  sample::applyLiveSetting(w.world, "clouds.coverage", 0.62);
  EXPECT_EQ(w.layer().coverage, 0.62f);
  sample::applyLiveSetting(w.world, "clouds.wind.directionDegrees", 90.0);
  EXPECT_NEAR(w.layer().windDirection.y, -1.0f, 1e-6f);  // towards -Z, as the scene reads it
  EXPECT_EQ(w.layer().windDirection, w.scene().clouds->settings.windDirection);
  sample::applyLiveSetting(w.world, "sun.timeOfDayHours", 9.5);
  w.world.view<const sample::TimeOfDay>().each(
      [](const sample::TimeOfDay& t) { EXPECT_EQ(t.hours, 9.5); });
  sample::applyLiveSetting(w.world, "exposure.compensationEv", -1.5);
  EXPECT_EQ(w.world.ctx().get<engine::render::Exposure>().compensationEv, -1.5f);
}

TEST(LiveSettings, RefusesWhatIsOutOfRangeUnknownOrAbsentByName) {
  LiveWorld w;
  EXPECT_NE(refusal(w.world, "clouds.coverage", 1.5).find("clouds.coverage: must be in"),
            std::string::npos);
  EXPECT_NE(refusal(w.world, "clouds.coverage", std::nan("")).find("clouds.coverage"),
            std::string::npos);
  EXPECT_NE(refusal(w.world, "clouds.colour", 0.5).find("no live setting \"clouds.colour\""),
            std::string::npos);
  EXPECT_EQ(w.layer().coverage, clouds::Settings{}.coverage) << "nothing applied";
  LiveWorld clear(false);
  EXPECT_NE(refusal(clear.world, "clouds.coverage", 0.5).find("the scene has nothing it tunes"),
            std::string::npos);
  EXPECT_EQ(refusal(clear.world, "sun.timeOfDayHours", 6.0), "");
}

TEST(LiveSettings, TheSceneToSaveHasTheCamerasPresetAndBudget) {
  LiveWorld w;
  w.world.get<clouds::ecs::CloudQuality>(w.camera).preset = clouds::Quality::High;
  EXPECT_EQ(sample::sceneToSave(w.world).camera.cloudQuality, clouds::Quality::High);
  EXPECT_EQ(sample::sceneToSave(w.world).camera.frameTargetMilliseconds, 0.0) << "fixed";
  w.world.emplace<clouds::ecs::CloudFrameBudget>(w.camera, clouds::ecs::CloudFrameBudget{20.0});
  EXPECT_EQ(sample::sceneToSave(w.world).camera.frameTargetMilliseconds, 20.0);
}

// A reloaded scene file (scene_hot_reload.h) applies what the file changed and nothing else:
// a clock the player set running keeps its time where the file left the time of day alone,
// and a change only a restart makes is said to.
TEST(SceneHotReload, AppliesWhatTheFileChangedAndSaysWhatWaitsForARestart) {
  LiveWorld w;
  w.world.view<sample::TimeOfDay>().each([](sample::TimeOfDay& t) { t.hours = 17.5; });
  sample::SceneDescription before = w.scene();
  sample::SceneDescription next = before;
  next.clouds->settings.coverage = 0.3f;
  next.exposure.compensationEv = 1.0;
  EXPECT_EQ(sample::applyReloadedScene(w.world, before, next), "applied");
  EXPECT_EQ(w.layer().coverage, 0.3f);
  EXPECT_EQ(w.world.ctx().get<engine::render::Exposure>().compensationEv, 1.0f);
  w.world.view<const sample::TimeOfDay>().each(
      [](const sample::TimeOfDay& t) { EXPECT_EQ(t.hours, 17.5); });
  EXPECT_EQ(w.scene().clouds->settings.coverage, 0.3f) << "what a save writes";

  before = next;
  next.terrain = sample::TerrainDescription{"default", false, std::nullopt};
  next.sun.timeOfDayHours = 8.0;
  EXPECT_NE(sample::applyReloadedScene(w.world, before, next).find("at restart"),
            std::string::npos);
  w.world.view<const sample::TimeOfDay>().each(
      [](const sample::TimeOfDay& t) { EXPECT_EQ(t.hours, 8.0); });
  EXPECT_FALSE(w.scene().terrain.has_value()) << "the running scene has no terrain yet";
}

}  // namespace
