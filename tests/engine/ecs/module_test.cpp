#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/ecs/app.h"
#include "engine/ecs/module.h"
#include "log_capture.h"
#include "test_components.h"

namespace {

using ecs_test::Position;
using ecs_test::Velocity;
using engine::ecs::App;
using engine::ecs::Module;
using engine::ecs::Phase;
using engine::ecs::Scheduler;
using engine::ecs::World;

struct Gravity {
  float acceleration = -9.8f;
};
struct GpuDevice {
  bool hasComputeQueue = false;
};

// Provides Gravity and a system applying it to Velocity.
class PhysicsModule final : public Module {
 public:
  std::string_view name() const override { return "physics"; }
  void install(World& world, Scheduler& scheduler) override {
    world.ctx().emplace<Gravity>();
    scheduler.add(Phase::Simulate, "physics.gravity", [](World& w) {
      const float g = w.ctx().get<Gravity>().acceleration;
      w.view<Velocity>().each([g](Velocity& v) { v.dy += g; });
    });
    scheduler.add(Phase::Simulate, "physics.integrate", [](World& w) {
      w.view<Position, const Velocity>().each([](Position& p, const Velocity& v) {
        p.x += v.dx;
        p.y += v.dy;
      });
    });
  }
};

// Needs a GpuDevice with a compute queue; skipped otherwise.
class CloudsModule final : public Module {
 public:
  std::string_view name() const override { return "clouds"; }
  bool supported(const World& world, std::string& reason) const override {
    const GpuDevice* device = world.ctx().tryGet<GpuDevice>();
    if (device == nullptr) {
      reason = "no GpuDevice in the world context";
      return false;
    }
    if (!device->hasComputeQueue) {
      reason = "device lacks a compute queue";
      return false;
    }
    return true;
  }
  void install(World&, Scheduler& scheduler) override {
    installed = true;
    scheduler.add(Phase::Render, "clouds.render", [](World&) {});
  }
  bool installed = false;
};

using test::LogCapture;

TEST(Module, InstallRegistersSingletonsAndSystems) {
  App app;
  EXPECT_TRUE(app.addModule<PhysicsModule>());
  EXPECT_TRUE(app.hasModule("physics"));
  EXPECT_TRUE(app.world().ctx().has<Gravity>());
  EXPECT_EQ(app.scheduler().systemNames(Phase::Simulate),
            (std::vector<std::string>{"physics.gravity", "physics.integrate"}));

  const auto e = app.world().create();
  app.world().emplace<Position>(e);
  app.world().emplace<Velocity>(e, 1.0f, 0.0f);
  app.runFrame();
  EXPECT_FLOAT_EQ(app.world().get<Position>(e).x, 1.0f);
  EXPECT_FLOAT_EQ(app.world().get<Position>(e).y, -9.8f);
  EXPECT_THROW(app.addModule<PhysicsModule>(), engine::Error);  // duplicate name
  EXPECT_EQ(app.installedModules(), (std::vector<std::string_view>{"physics"}));
}

TEST(Module, UnsupportedModuleIsSkippedWithAWarning) {
  LogCapture capture;
  App app;
  EXPECT_FALSE(app.addModule<CloudsModule>());
  EXPECT_FALSE(app.hasModule("clouds"));
  EXPECT_EQ(app.skippedModules(), (std::vector<std::string>{"clouds"}));
  EXPECT_EQ(app.scheduler().systemCount(), 0u);
  ASSERT_EQ(capture.warnings.size(), 1u);
  EXPECT_NE(capture.warnings[0].find("clouds"), std::string::npos) << capture.warnings[0];
  EXPECT_NE(capture.warnings[0].find("no GpuDevice"), std::string::npos) << capture.warnings[0];
  app.runFrame();  // the rest still runs
}

// Supported on paper, but creating its GPU objects fails: install() says so by throwing
// ModuleUnsupported before it registers anything.
class FailingGpuModule final : public Module {
 public:
  std::string_view name() const override { return "volumetrics"; }
  void install(World&, Scheduler&) override {
    throw engine::ecs::ModuleUnsupported("the device cannot create the volume textures");
  }
};

TEST(Module, AModuleThatFindsItCannotRunWhileInstallingIsSkippedWithAWarning) {
  LogCapture capture;
  App app;
  EXPECT_FALSE(app.addModule<FailingGpuModule>());
  EXPECT_FALSE(app.hasModule("volumetrics"));
  EXPECT_EQ(app.skippedModules(), (std::vector<std::string>{"volumetrics"}));
  ASSERT_EQ(capture.warnings.size(), 1u);
  EXPECT_NE(capture.warnings[0].find("volume textures"), std::string::npos) << capture.warnings[0];
  EXPECT_TRUE(app.addModule<PhysicsModule>()) << "the rest of the app still installs";
  app.runFrame();
}

TEST(Module, InstallModuleChecksSupportAgainstTheWorld) {
  LogCapture capture;
  World world;
  Scheduler scheduler;
  CloudsModule clouds;
  world.ctx().emplace<GpuDevice>(false);
  EXPECT_FALSE(engine::ecs::installModule(clouds, world, scheduler));
  EXPECT_FALSE(clouds.installed);
  ASSERT_EQ(capture.warnings.size(), 1u);
  EXPECT_NE(capture.warnings[0].find("compute queue"), std::string::npos);

  world.ctx().get<GpuDevice>().hasComputeQueue = true;
  EXPECT_TRUE(engine::ecs::installModule(clouds, world, scheduler));
  EXPECT_TRUE(clouds.installed);
  EXPECT_TRUE(scheduler.contains("clouds.render"));
  EXPECT_EQ(capture.warnings.size(), 1u);
}

}  // namespace
