// Input scripts: frame-indexed events parse strictly and drive the same InputState and events
// the window and the game use.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/error.h"
#include "engine/ecs/world.h"
#include "game/input_script.h"

namespace {

namespace fs = std::filesystem;
using engine::platform::InputState;
using engine::platform::Key;

fs::path writeScript(const std::string& name, const std::string& json) {
  const fs::path dir = fs::temp_directory_path() / "cloudscape_script_tests";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << json;
  return path;
}

TEST(InputScript, DrivesKeysMouseAndEventsFrameByFrame) {
  const auto script = sample::InputScript::load(writeScript("good.json", R"({"events": [
    {"frame": 2, "release": ["W"]},
    {"frame": 0, "press": ["W", "Up"]},
    {"frame": 1, "mouse": [10, -4, 0]},
    {"frame": 1, "camera": {"position": [5, 600, 7], "yawDegrees": 30, "speedMetresPerSecond": 0}},
    {"frame": 1, "timeOfDayHours": 7.5},
    {"frame": 3, "capture": "shot_1"},
    {"frame": 4, "exit": true}]})"));
  EXPECT_EQ(script.lastFrame(), 4u);
  engine::ecs::World world;
  world.ctx().emplace<sample::ExitRequest>();
  engine::ecs::EventReader<sample::SetCameraPose> poses;
  engine::ecs::EventReader<sample::SetTimeOfDay> times;
  engine::ecs::EventReader<sample::CaptureFrame> captures;
  InputState input;
  for (std::uint64_t frame = 0; frame < 5; ++frame) {
    input.beginFrame();
    script.apply(frame, input, world);
    if (frame == 0) {
      EXPECT_TRUE(input.isDown(Key::W) && input.isDown(Key::Up));
      EXPECT_TRUE(input.wasPressed(Key::W));
    }
    if (frame == 1) {
      EXPECT_TRUE(input.isDown(Key::W)) << "keys stay down until released";
      EXPECT_FALSE(input.wasPressed(Key::W));
      EXPECT_DOUBLE_EQ(input.mouseDeltaX, 10.0);
      int n = 0;
      for (const auto& p : poses.read(world.events<sample::SetCameraPose>())) {
        EXPECT_EQ(p.position, glm::dvec3(5, 600, 7));
        EXPECT_DOUBLE_EQ(p.yawDegrees, 30.0);
        ++n;
      }
      EXPECT_EQ(n, 1);
      for (const auto& t : times.read(world.events<sample::SetTimeOfDay>()))
        EXPECT_DOUBLE_EQ(t.hours, 7.5);
    }
    if (frame == 2) {
      EXPECT_FALSE(input.isDown(Key::W));
    }
    if (frame == 3) {
      int n = 0;
      for (const auto& c : captures.read(world.events<sample::CaptureFrame>())) {
        EXPECT_EQ(c.name, "shot_1");
        ++n;
      }
      EXPECT_EQ(n, 1);
    }
    world.updateEvents();
  }
  EXPECT_TRUE(world.ctx().get<sample::ExitRequest>().requested);
}

TEST(InputScript, MalformedScriptsAreRejectedWithThePath) {
  struct Case {
    const char* json;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"events": [{"frame": 0, "press": ["Warp"]}]})", "events[0].press: unknown key \"Warp\""},
      {R"({"events": [{"frame": 0, "set": {"clouds.colour": 1}}]})",
       "events[0].set.clouds.colour: no such live setting"},
      {R"({"events": [{"frame": 0, "set": {"clouds.coverage": 2}}]})",
       "events[0].set.clouds.coverage"},
      {R"({"events": [{"frame": 0}]})", "events[0]: needs exactly one action"},
      {R"({"events": [{"frame": 0, "press": ["W"], "exit": true}]})", "needs exactly one action"},
      {R"({"events": [{"frame": -1, "exit": true}]})", "events[0].frame: must be in"},
      {R"({"events": [{"frame": 0, "capture": "../escape"}]})",
       "events[0].capture: must be a file stem"},
      {R"({"events": [{"frame": 0, "jump": true}]})", "events[0]: needs exactly one action"},
      {R"({"evnts": []})", "events: is required"},
  };
  int i = 0;
  for (const Case& c : cases) {
    const fs::path path = writeScript("bad" + std::to_string(i++) + ".json", c.json);
    try {
      sample::InputScript::load(path);
      ADD_FAILURE() << "accepted: " << c.json;
    } catch (const engine::Error& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos);
    }
  }
}

}  // namespace
