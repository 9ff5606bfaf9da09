#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/ecs/context.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/world.h"
#include "test_components.h"

namespace {

using ecs_test::Tracked;
using engine::ecs::Context;
using engine::ecs::FrameTime;
using engine::ecs::World;

struct Settings {
  int quality = 1;
  std::string name = "default";
};

TEST(Context, EmplaceGetTryGetHasErase) {
  World world;
  Context& ctx = world.ctx();
  EXPECT_FALSE(ctx.has<Settings>());
  EXPECT_EQ(ctx.tryGet<Settings>(), nullptr);
  Settings& settings = ctx.emplace<Settings>(3, "high");
  EXPECT_TRUE(ctx.has<Settings>());
  EXPECT_EQ(&ctx.get<Settings>(), &settings);
  EXPECT_EQ(ctx.get<Settings>().name, "high");
  const World& constWorld = world;
  EXPECT_EQ(constWorld.ctx().get<Settings>().quality, 3);
  EXPECT_EQ(ctx.size(), 1u);

  // Other types do not move existing instances.
  ctx.emplace<FrameTime>();
  ctx.emplace<int>(5);
  EXPECT_EQ(&ctx.get<Settings>(), &settings);

  EXPECT_THROW(ctx.emplace<Settings>(), engine::Error);
  ctx.emplaceOrReplace<Settings>(7, "ultra");
  EXPECT_EQ(settings.quality, 7);  // replaced in place

  EXPECT_TRUE(ctx.erase<Settings>());
  EXPECT_FALSE(ctx.erase<Settings>());
  EXPECT_FALSE(ctx.has<Settings>());
  EXPECT_EQ(ctx.size(), 2u);
  try {
    ctx.get<Settings>();
    FAIL() << "expected engine::Error";
  } catch (const engine::Error& error) {
    EXPECT_NE(std::string(error.what()).find("Settings"), std::string::npos) << error.what();
  }
}

TEST(Context, OneInstancePerTypeDestroyedNewestFirst) {
  static std::vector<int> order;
  order.clear();
  struct First {
    ~First() { order.push_back(1); }
  };
  struct Second {
    ~Second() { order.push_back(2); }
  };
  Tracked::reset();
  {
    Context ctx;
    ctx.emplace<First>();
    ctx.emplace<Tracked>(4);
    ctx.emplace<Second>();
    EXPECT_EQ(Tracked::live, 1);
  }
  EXPECT_EQ(order, (std::vector<int>{2, 1}));
  EXPECT_EQ(Tracked::live, 0);
  EXPECT_EQ(Tracked::constructed, Tracked::destroyed);
}

TEST(Context, FrameTimeIsSetByTheCaller) {
  World world;
  FrameTime& time = world.ctx().emplace<FrameTime>();
  time = time.next(0.5);
  time = time.next(0.25);
  EXPECT_EQ(time.frameIndex, 2u);
  EXPECT_DOUBLE_EQ(time.elapsedSeconds, 0.75);
  EXPECT_DOUBLE_EQ(time.deltaSeconds, 0.25);
}

}  // namespace
