// The live settings (what the settings panel and a script's "set" change): each writes the
// world and the scene that a save writes alike, refuses what is out of range or absent by name,
// and the scene to save folds in the camera's preset and budget.
#include "game/live_settings.h"
#include "game/scene_hot_reload.h"
#include "game/water.h"

#include <gtest/gtest.h>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/cloud_frame.h"
#include "clouds/ecs/frame_budget.h"
#include "clouds/ecs/lightning.h"
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
      // A storm's layer with god rays: every live setting has what it tunes.
      scene.clouds = sample::CloudDescription{};
      scene.clouds->settings.godRaySamples = sample::kSceneGodRaySamples;
      scene.lightning = sample::LightningDescription{};
      world.emplace<clouds::ecs::CloudLayer>(world.create(),
                                             clouds::ecs::CloudLayer{scene.clouds->settings});
      world.emplace<clouds::ecs::LightningStorm>(world.create(), scene.lightning->storm);
    }
    world.emplace<sample::TimeOfDay>(world.create(), sample::TimeOfDay{});
    world.ctx().emplace<engine::render::Exposure>();
    camera = world.create();
    world.emplace<engine::render::Camera>(camera, engine::render::Camera{});
    world.emplace<clouds::ecs::CloudQuality>(camera, clouds::ecs::CloudQuality{});
    world.ctx().emplace<sample::LiveScene>(
        sample::LiveScene{scene, "unused.json", {}, {}, {}, scene});
  }
  const sample::LiveScene& live() { return world.ctx().get<sample::LiveScene>(); }
  const sample::SceneDescription& scene() { return live().scene; }
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
    // A switch goes off (the scene has it on); a slider to 3/8 of its range.
    const double value = setting.isSwitch ? 0.0 : setting.min + 0.375 * (setting.max - setting.min);
    ASSERT_TRUE(setting.available(w.live()));
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

// The panel's effect switches: god rays off and on again reach the layer (and the preset's
// own sample count while on), lightning's rate 0 stops the storm's strikes; a scene loaded
// without an effect has no switch for it (turning it on would build its passes mid-flight).
TEST(LiveSettings, EffectsSwitchWhereTheSceneWasLoadedWithThem) {
  LiveWorld w;
  sample::applyLiveSetting(w.world, "clouds.godRays", 0.0);
  EXPECT_EQ(w.layer().godRaySamples, 0u);
  EXPECT_EQ(clouds::ecs::cloudSettings(w.world).godRaySamples, 0u);
  sample::applyLiveSetting(w.world, "clouds.godRays", 1.0);
  EXPECT_EQ(w.layer().godRaySamples, sample::kSceneGodRaySamples);
  EXPECT_GT(clouds::ecs::cloudSettings(w.world).godRaySamples, 0u);
  EXPECT_TRUE(sample::sceneToSave(w.world).clouds->settings.godRaySamples > 0);

  sample::applyLiveSetting(w.world, "clouds.shadows", 0.0);
  EXPECT_EQ(w.layer().shadowCascades, 0u);
  EXPECT_EQ(clouds::ecs::cloudSettings(w.world).shadowCascades, 0u);
  EXPECT_EQ(sample::sceneToSave(w.world).clouds->settings.shadowCascades, 0u);
  sample::applyLiveSetting(w.world, "clouds.shadows", 1.0);
  EXPECT_EQ(w.layer().shadowCascades, w.live().loaded.clouds->settings.shadowCascades);
  EXPECT_GT(w.layer().shadowCascades, 0u);

  sample::applyLiveSetting(w.world, "lightning.strikesPerMinute", 0.0);
  w.world.view<const clouds::ecs::LightningStorm>().each(
      [](const clouds::ecs::LightningStorm& storm) { EXPECT_EQ(storm.strikesPerMinute, 0.0); });
  EXPECT_EQ(sample::sceneToSave(w.world).lightning->storm.strikesPerMinute, 0.0);

  LiveWorld without;
  auto& live = without.world.ctx().get<sample::LiveScene>();
  live.loaded.clouds->settings.godRaySamples = 0;
  live.loaded.clouds->settings.shadowCascades = 0;
  live.loaded.lightning.reset();
  EXPECT_NE(refusal(without.world, "clouds.godRays", 1.0).find("the scene has nothing it tunes"),
            std::string::npos);
  EXPECT_NE(refusal(without.world, "clouds.shadows", 1.0).find("the scene has nothing it tunes"),
            std::string::npos);
  EXPECT_NE(refusal(without.world, "lightning.strikesPerMinute", 3.0)
                .find("the scene has nothing it tunes"),
            std::string::npos);
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

// "from here": the saved scene starts where the camera is, heading and pitch as the scene's
// start reads them (the roll levelled), at its airspeed; "save scene" keeps the scene's start.
TEST(LiveSettings, SavingFromHereStartsTheSceneWhereTheCameraIs) {
  LiveWorld w;
  auto& camera = w.world.get<engine::render::Camera>(w.camera);
  camera.position = glm::dvec3(1200.0, 2400.0, -800.0);
  const glm::dquat yaw = glm::angleAxis(glm::radians(130.0), glm::dvec3(0, 1, 0));
  const glm::dquat pitch = glm::angleAxis(glm::radians(-12.0), glm::dvec3(1, 0, 0));
  const glm::dquat roll = glm::angleAxis(glm::radians(25.0), glm::dvec3(0, 0, 1));
  camera.orientation = yaw * pitch * roll;
  w.world.emplace<sample::Aircraft>(w.camera, sample::Aircraft{240.0});
  const sample::CameraDescription here =
      sample::sceneToSave(w.world, sample::SavedStart::Here).camera;
  EXPECT_EQ(here.position, camera.position);
  EXPECT_NEAR(here.yawDegrees, 130.0, 1e-9);
  EXPECT_NEAR(here.pitchDegrees, -12.0, 1e-9);
  EXPECT_EQ(here.speedMetresPerSecond, 240.0);
  const sample::CameraDescription start = sample::sceneToSave(w.world).camera;
  EXPECT_EQ(start.position, sample::CameraDescription{}.position);
  EXPECT_EQ(start.yawDegrees, 0.0);

  // Straight down has no heading: the start is kept within the 89 degrees a scene accepts.
  camera.orientation = glm::angleAxis(glm::radians(-90.0), glm::dvec3(1, 0, 0));
  EXPECT_EQ(sample::sceneToSave(w.world, sample::SavedStart::Here).camera.pitchDegrees, -89.0);
}

// A knob of the cloud preset (the panel's "cloud preset's knobs"): shows the preset's value
// until set; set, it reaches the clouds' settings, fixes the preset (the governor's budget
// goes) and is saved; the preset's other values stay.
TEST(LiveSettings, AKnobTunesTheCameraPresetAndFixesIt) {
  LiveWorld w;
  w.world.get<clouds::ecs::CloudQuality>(w.camera).preset = clouds::Quality::High;
  w.world.emplace<clouds::ecs::CloudFrameBudget>(w.camera, clouds::ecs::CloudFrameBudget{20.0});
  sample::syncLiveScene(w.world);
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  const sample::LiveSetting* light = sample::findLiveSetting("camera.cloudKnobs.lightSteps");
  ASSERT_NE(light, nullptr);
  EXPECT_EQ(light->get(w.scene()), double(high.lightSteps));

  sample::applyLiveSetting(w.world, "camera.cloudKnobs.lightSteps", 2.0);
  const clouds::Settings tuned = clouds::ecs::cloudSettings(w.world);
  EXPECT_EQ(tuned.lightSteps, 2u);
  EXPECT_EQ(tuned.maxViewSteps, high.maxViewSteps);
  EXPECT_EQ(tuned.viewStepMetres, high.viewStepMetres);
  EXPECT_EQ(w.world.tryGet<clouds::ecs::CloudFrameBudget>(w.camera), nullptr);
  const sample::SceneDescription saved = sample::sceneToSave(w.world);
  EXPECT_EQ(saved.camera.cloudQuality, clouds::Quality::High);
  EXPECT_EQ(saved.camera.cloudKnobs.lightSteps, std::optional<std::uint32_t>(2u));
  EXPECT_FALSE(saved.camera.cloudKnobs.maxViewSteps.has_value());
  EXPECT_EQ(saved.camera.frameTargetMilliseconds, 0.0);
  EXPECT_NE(refusal(w.world, "camera.cloudKnobs.lightSteps", 99.0)
                .find("camera.cloudKnobs.lightSteps: must be in"),
            std::string::npos);
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

// The water's level, colour and clarity apply while flying (the renderer reads them every frame);
// water brought in or taken away waits for a restart.
TEST(SceneHotReload, TheWatersLevelAppliesWhileFlying) {
  LiveWorld w;
  sample::SceneDescription before = w.scene();
  before.water = sample::WaterDescription{215.0, glm::dvec3(0.01, 0.03, 0.04), 0.35};
  w.world.ctx().get<sample::LiveScene>().scene.water = before.water;
  w.world.ctx().emplace<sample::WaterSurface>(sample::WaterSurface{215.0});
  sample::SceneDescription next = before;
  next.water->levelMetres = 240.0;
  next.water->clarity = 0.1;
  EXPECT_EQ(sample::applyReloadedScene(w.world, before, next), "applied");
  EXPECT_EQ(w.world.ctx().get<sample::WaterSurface>().levelMetres, 240.0);
  EXPECT_FLOAT_EQ(float(w.world.ctx().get<sample::WaterSurface>().clarity), 0.1f);
  EXPECT_EQ(w.scene().water->levelMetres, 240.0) << "what a save writes";

  before = next;
  next.water.reset();
  EXPECT_NE(sample::applyReloadedScene(w.world, before, next).find("water on or off"),
            std::string::npos);
  EXPECT_EQ(w.world.ctx().get<sample::WaterSurface>().levelMetres, 240.0) << "until a restart";
}

}  // namespace
