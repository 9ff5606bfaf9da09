#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"
#include "test_components.h"

namespace {

using ecs_test::Health;
using engine::ecs::Entity;
using engine::ecs::EventReader;
using engine::ecs::FrameTime;
using engine::ecs::Phase;
using engine::ecs::Scheduler;
using engine::ecs::World;

TEST(Scheduler, RunsPhasesInOrderAndSystemsInInsertionOrder) {
  World world;
  Scheduler scheduler;
  std::vector<std::string> log;
  auto record = [&log](std::string name) { return [&log, name](World&) { log.push_back(name); }; };
  // Added out of phase order on purpose.
  scheduler.add(Phase::PostRender, "post", record("post"));
  scheduler.add(Phase::Render, "render", record("render"));
  scheduler.add(Phase::Simulate, "sim-b", record("sim-b"));
  scheduler.add(Phase::Input, "input", record("input"));
  scheduler.add(Phase::Simulate, "sim-a", record("sim-a"));
  scheduler.add(Phase::PreRender, "pre", record("pre"));
  scheduler.add(Phase::Simulate, "sim-c", record("sim-c"));

  scheduler.runFrame(world);
  EXPECT_EQ(
      log, (std::vector<std::string>{"input", "sim-b", "sim-a", "sim-c", "pre", "render", "post"}));
  log.clear();
  scheduler.runFrame(world);
  EXPECT_EQ(log.size(), 7u);

  EXPECT_EQ(scheduler.systemNames(Phase::Simulate),
            (std::vector<std::string>{"sim-b", "sim-a", "sim-c"}));
  EXPECT_EQ(scheduler.systemNames(Phase::Input), (std::vector<std::string>{"input"}));
  EXPECT_EQ(scheduler.systemCount(), 7u);
  EXPECT_EQ(scheduler.systemCount(Phase::Render), 1u);
  EXPECT_TRUE(scheduler.contains("pre"));
  EXPECT_FALSE(scheduler.contains("missing"));
  EXPECT_EQ(scheduler.describe(),
            "Input: input\nSimulate: sim-b, sim-a, sim-c\nPreRender: pre\nRender: render\n"
            "PostRender: post\n");
}

TEST(Scheduler, RejectsBadSystems) {
  Scheduler scheduler;
  World world;
  scheduler.add(Phase::Input, "a", [](World&) {});
  EXPECT_THROW(scheduler.add(Phase::Render, "a", [](World&) {}), engine::Error);
  EXPECT_THROW(scheduler.add(Phase::Render, "", [](World&) {}), engine::Error);
  EXPECT_THROW(scheduler.add(Phase::Render, "empty", nullptr), engine::Error);
  scheduler.add(Phase::Simulate, "adds",
                [&scheduler](World&) { scheduler.add(Phase::Render, "late", [](World&) {}); });
  EXPECT_THROW(scheduler.runFrame(world), engine::Error);
  EXPECT_FALSE(scheduler.contains("late"));
  EXPECT_TRUE(scheduler.currentSystem().empty());  // reset after the exception
}

TEST(Scheduler, FlushesDeferredAfterEachSystemAndUpdatesEventsAtFrameEnd) {
  World world;
  Scheduler scheduler;
  const Entity doomed = world.create();
  world.emplace<Health>(doomed, 1);
  bool aliveInSameSystem = false;
  bool aliveInNextSystem = true;
  std::string nameDuringRun;
  scheduler.add(Phase::Simulate, "kill", [&](World& w) {
    w.destroyDeferred(doomed);
    aliveInSameSystem = w.alive(doomed);
    nameDuringRun = std::string(scheduler.currentSystem());
  });
  scheduler.add(Phase::Simulate, "observe", [&](World& w) { aliveInNextSystem = w.alive(doomed); });

  // Sent in PostRender of frame 0, read in Input of frame 1, gone by frame 2.
  EventReader<int> reader;
  std::vector<std::size_t> seenPerFrame;
  scheduler.add(Phase::Input, "read",
                [&](World& w) { seenPerFrame.push_back(reader.read(w.events<int>()).size()); });
  scheduler.add(Phase::PostRender, "send", [](World& w) {
    if (w.ctx().get<FrameTime>().frameIndex == 0) w.events<int>().send(42);
  });

  FrameTime& time = world.ctx().emplace<FrameTime>();
  scheduler.runFrame(world);
  EXPECT_TRUE(aliveInSameSystem);
  EXPECT_FALSE(aliveInNextSystem);
  EXPECT_EQ(nameDuringRun, "kill");
  EXPECT_EQ(world.deferredCount(), 0u);
  for (int frame = 1; frame < 4; ++frame) {
    time = time.next(1.0 / 60.0);
    scheduler.runFrame(world);
  }
  EXPECT_EQ(seenPerFrame, (std::vector<std::size_t>{0, 1, 0, 0}));
  EXPECT_TRUE(world.events<int>().empty());
}

}  // namespace
