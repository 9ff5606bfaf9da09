// A camera's frame budget without a GPU: the "cloud frame budget" system fed with a synthetic
// GPU frame time (each preset a known cost) sets the camera's preset, stops when the budget
// goes, and refuses a budget outside the ladder by name.
#include "clouds/ecs/frame_budget.h"

#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/cloud_frame.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"
#include "engine/render/gpu_frame_time.h"
#include "engine/render/scene_components.h"

namespace {

using clouds::Quality;

std::vector<Quality> governed(engine::ecs::World& world) {
  const std::span<const Quality> presets = clouds::ecs::governedPresets(world);
  return {presets.begin(), presets.end()};
}

struct BudgetWorld {
  engine::ecs::World world;
  engine::ecs::Scheduler scheduler;
  engine::ecs::Entity camera;
  // What each preset's frame costs on the GPU, milliseconds.
  std::map<Quality, double> cost = {
      {Quality::Low, 9.0}, {Quality::Medium, 12.0}, {Quality::High, 28.0}, {Quality::Ultra, 70.0}};
  // What each preset's frame takes on the wall clock (the GPU's time, the CPU's and the
  // present), milliseconds.
  std::map<Quality, double> wallCost = {
      {Quality::Low, 20.0}, {Quality::Medium, 30.0}, {Quality::High, 50.0}, {Quality::Ultra, 95.0}};
  std::uint64_t frame = 0;
  std::vector<Quality> rendered;  // the preset of each frame so far

  BudgetWorld() {
    world.emplace<clouds::ecs::CloudLayer>(world.create(), clouds::ecs::CloudLayer{});
    camera = world.create();
    world.emplace<engine::render::Camera>(camera, engine::render::Camera{});
    world.emplace<clouds::ecs::CloudQuality>(camera, clouds::ecs::CloudQuality{Quality::Medium});
    clouds::ecs::installFrameBudget(world, scheduler);
  }
  Quality preset() { return world.get<clouds::ecs::CloudQuality>(camera).preset; }
  // Frames whose GPU time is what the camera's preset costs (measured as the renderer does,
  // two frames late), and whose wall time is its wall cost (measured by the frame loop, one
  // frame late).
  void run(int frames) {
    for (int i = 0; i < frames; ++i, ++frame) {
      if (frame >= 1) {
        world.ctx().emplaceOrReplace<engine::ecs::WallFrameTime>(wallCost.at(rendered[frame - 1]),
                                                                 frame - 1, true);
      }
      if (frame >= 2) {
        engine::render::GpuFrameTime time;
        time.milliseconds = cost.at(rendered[frame - 2]);
        time.frameIndex = frame - 2;
        time.measured = true;
        world.ctx().emplaceOrReplace<engine::render::GpuFrameTime>(time);
      }
      scheduler.runFrame(world);
      rendered.push_back(preset());
    }
  }
  const clouds::ecs::CloudGovernorStatus& status() {
    return world.ctx().get<clouds::ecs::CloudGovernorStatus>();
  }
};

TEST(CloudFrameBudget, ChoosesTheDearestPresetThatHoldsTheTarget) {
  BudgetWorld w;
  w.world.emplace<clouds::ecs::CloudFrameBudget>(w.camera, clouds::ecs::CloudFrameBudget{33.3});
  w.run(600);
  EXPECT_EQ(w.preset(), Quality::High);
  EXPECT_TRUE(w.status().active);
  EXPECT_EQ(w.status().preset, Quality::High);
  EXPECT_EQ(w.status().changes, 1u);
  EXPECT_NEAR(w.status().judgedMilliseconds, 28.0, 1e-9);
  EXPECT_STREQ(w.status().reason, "holding");
  // The feature prepares every preset between the floor and the ceiling ahead.
  EXPECT_EQ(governed(w.world),
            (std::vector<Quality>{Quality::Low, Quality::Medium, Quality::High, Quality::Ultra}));

  // A heavier scene: down to what fits.
  w.cost[Quality::High] = 40.0;
  w.run(200);
  EXPECT_EQ(w.preset(), Quality::Medium);
}

// The same costs judged on the wall clock: High's 50 ms does not fit 33.3, so it holds Medium.
TEST(CloudFrameBudget, AWallClockBudgetJudgesTheWallTime) {
  BudgetWorld w;
  clouds::ecs::CloudFrameBudget budget{33.3};
  budget.source = clouds::ecs::FrameTimeSource::WallFrame;
  w.world.emplace<clouds::ecs::CloudFrameBudget>(w.camera, budget);
  w.run(600);
  EXPECT_EQ(w.preset(), Quality::Medium);
  EXPECT_EQ(w.status().changes, 0u);
  EXPECT_NEAR(w.status().judgedMilliseconds, 30.0, 1e-9);

  // Heavier on the wall clock only: down to Low, though the GPU time would still fit.
  w.wallCost[Quality::Medium] = 40.0;
  w.run(200);
  EXPECT_EQ(w.preset(), Quality::Low);
}

// A budget switched to the other clock starts again: what it judged on the GPU's time is not
// the wall clock's. (High holds 33.3 ms on the GPU; on the wall clock it takes 50.)
TEST(CloudFrameBudget, ABudgetThatChangesClocksStartsAgain) {
  BudgetWorld w;
  w.world.emplace<clouds::ecs::CloudFrameBudget>(w.camera, clouds::ecs::CloudFrameBudget{33.3});
  w.run(600);
  ASSERT_EQ(w.preset(), Quality::High);
  ASSERT_EQ(w.status().changes, 1u);
  w.world.get<clouds::ecs::CloudFrameBudget>(w.camera).source =
      clouds::ecs::FrameTimeSource::WallFrame;
  w.run(300);
  EXPECT_EQ(w.preset(), Quality::Medium);
  EXPECT_EQ(w.status().changes, 1u) << "counted from the switch: High to Medium";
  EXPECT_NEAR(w.status().judgedMilliseconds, 30.0, 1e-9);
}

TEST(CloudFrameBudget, KeepsWithinItsFloorAndCeiling) {
  BudgetWorld w;
  w.world.emplace<clouds::ecs::CloudFrameBudget>(
      w.camera, clouds::ecs::CloudFrameBudget{1000.0, Quality::Low, Quality::Medium});
  w.run(600);
  EXPECT_EQ(w.preset(), Quality::Medium);
  EXPECT_EQ(governed(w.world), (std::vector<Quality>{Quality::Low, Quality::Medium}));
}

TEST(CloudFrameBudget, WithoutABudgetThePresetIsLeftAlone) {
  BudgetWorld w;
  w.world.emplace<clouds::ecs::CloudFrameBudget>(w.camera, clouds::ecs::CloudFrameBudget{1000.0});
  w.run(100);
  ASSERT_EQ(w.preset(), Quality::High);
  w.world.remove<clouds::ecs::CloudFrameBudget>(w.camera);
  w.world.get<clouds::ecs::CloudQuality>(w.camera).preset = Quality::Low;  // a number key
  w.run(600);
  EXPECT_EQ(w.preset(), Quality::Low);
  EXPECT_FALSE(w.status().active);
  EXPECT_TRUE(clouds::ecs::governedPresets(w.world).empty());
}

TEST(CloudFrameBudget, ABudgetOffTheLadderIsRefusedByName) {
  BudgetWorld w;
  w.world.emplace<clouds::ecs::CloudFrameBudget>(
      w.camera, clouds::ecs::CloudFrameBudget{33.3, Quality::Low, Quality::Reference});
  w.run(100);
  EXPECT_EQ(w.preset(), Quality::Medium);
  EXPECT_FALSE(w.status().active);
  EXPECT_NE(w.status().error.find("CloudFrameBudget.ceiling"), std::string::npos)
      << w.status().error;
  EXPECT_TRUE(clouds::ecs::governedPresets(w.world).empty());

  w.world.get<clouds::ecs::CloudFrameBudget>(w.camera) =
      clouds::ecs::CloudFrameBudget{-1.0, Quality::Low, Quality::Ultra};
  w.run(10);
  EXPECT_NE(w.status().error.find("targetMilliseconds"), std::string::npos) << w.status().error;

  clouds::ecs::CloudFrameBudget quantile{33.3};
  quantile.judgedQuantile = 1.0;
  w.world.get<clouds::ecs::CloudFrameBudget>(w.camera) = quantile;
  w.run(10);
  EXPECT_NE(w.status().error.find("judgedQuantile"), std::string::npos) << w.status().error;
}

}  // namespace
