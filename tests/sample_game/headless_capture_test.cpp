// Runs the sample binary headless, as a user would, and checks what it writes: the exit code
// (non-zero on any validation message), image sizes and content (sky above, terrain below,
// clouds, HDR in the EXR, nothing non-finite), determinism, the pass list each kind of scene
// gets, flying over a user's glTF, and clear failures for bad arguments and scenes.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/assets/image_io.h"
#include "engine/core/json_reader.h"
#include "sample_runs.h"
#include "vdb_test_files.h"

namespace {

namespace fs = std::filesystem;
using engine::assets::ImageRgba32f;
using namespace sample_tests;

// The frame series (--frame-series) by column name: each row's field, as written.
std::map<std::string, std::vector<std::string>> readFrameSeries(const fs::path& file) {
  const auto split = [](const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
    return fields;
  };
  std::ifstream in(file);
  std::string line;
  std::map<std::string, std::vector<std::string>> columns;
  if (!std::getline(in, line)) return columns;
  const std::vector<std::string> names = split(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = split(line);
    for (std::size_t i = 0; i < names.size(); ++i)
      columns[names[i]].push_back(i < fields.size() ? fields[i] : "");
  }
  return columns;
}

std::vector<double> numbers(const std::vector<std::string>& fields) {
  std::vector<double> values;
  for (const std::string& f : fields) values.push_back(std::stod(f));
  return values;
}

TEST(HeadlessCapture, WritesPngAndExrOfTheLastFrame) {
  const fs::path dir = freshDir("last");
  ASSERT_EQ(runSample("--headless --frames 2 --width 160 --height 90 --validation --capture " +
                      dir.string()),
            0);
  ASSERT_FALSE(fs::exists(dir / "frame_0000.png")) << "only the last frame by default";
  const ImageRgba32f png = engine::assets::readImage(dir / "frame_0001.png");
  const ImageRgba32f exr = engine::assets::readImage(dir / "frame_0001.exr");
  ASSERT_EQ(png.width, 160u);
  ASSERT_EQ(png.height, 90u);
  ASSERT_EQ(exr.width, 160u);
  ASSERT_EQ(exr.height, 90u);
  for (float v : exr.pixels) ASSERT_TRUE(std::isfinite(v));

  // The default scene: terrain fills the bottom rows (green over blue), the top row is sky
  // (blue over red) or cloud, and somewhere there are white clouds (near-grey, bright). (Sunlit
  // ground and the blue sky have similar luminances in physical units: colour tells them apart.)
  double topBlueness = 0.0, bottomBlueness = 0.0;
  for (std::uint32_t x = 0; x < png.width; ++x) {
    const float* top = png.at(x, 1);
    const float* bottom = png.at(x, png.height - 2);
    topBlueness += top[2] - top[0];
    bottomBlueness += bottom[2] - bottom[0];
    EXPECT_GT(bottom[1], bottom[2]) << "the ground in front should be terrain, not sky";
  }
  EXPECT_GT(topBlueness, 0.1 * png.width) << "a blue sky above";
  EXPECT_LT(bottomBlueness, 0.0) << "warm ground below";
  int cloudy = 0;
  for (std::uint32_t y = 0; y < png.height / 2; ++y) {
    for (std::uint32_t x = 0; x < png.width; ++x) {
      const float* p = png.at(x, y);
      const bool grey = std::abs(p[0] - p[2]) < 0.08f && p[0] > 0.55f;
      cloudy += grey ? 1 : 0;
    }
  }
  EXPECT_GT(cloudy, 200) << "no white clouds in the upper half";
}

TEST(HeadlessCapture, CaptureAllWritesEveryFrameAndRunsAreDeterministic) {
  const fs::path a = freshDir("all_a");
  const fs::path b = freshDir("all_b");
  const std::string common =
      "--headless --frames 2 --fixed-dt 0.5 --width 96 --height 54 --capture-all --capture ";
  ASSERT_EQ(runSample(common + a.string()), 0);
  ASSERT_EQ(runSample(common + b.string()), 0);
  for (const char* name : {"frame_0000.png", "frame_0001.png", "frame_0001.exr"}) {
    const ImageRgba32f x = engine::assets::readImage(a / name);
    const ImageRgba32f y = engine::assets::readImage(b / name);
    ASSERT_EQ(x.pixels, y.pixels) << name << " differs between identical runs";
  }
  // The aircraft flies: consecutive frames differ.
  EXPECT_NE(engine::assets::readImage(a / "frame_0000.png").pixels,
            engine::assets::readImage(a / "frame_0001.png").pixels);
}

// A run of the sample: a scene, and a script or none.
struct SceneRun {
  std::string name;  // the test's name: letters, digits and underscores
  std::string scene;
  std::string script;
};

std::vector<SceneRun> shippedScenes() {
  std::vector<SceneRun> runs;
  for (const auto& entry : fs::directory_iterator(fs::path(SAMPLE_ASSET_DIR) / "scenes")) {
    if (entry.path().extension() == ".json")
      runs.push_back({entry.path().stem().string(), entry.path().string(), ""});
  }
  std::sort(runs.begin(), runs.end(),
            [](const SceneRun& a, const SceneRun& b) { return a.name < b.name; });
  return runs;
}

// Every shipped scene, a scripted ground strike in the storm, and weather (a region's too)
// turning from the first frame (the shipped scenes hold their first state for a while).
std::vector<SceneRun> scenesAndChanges() {
  std::vector<SceneRun> runs = shippedScenes();
  runs.push_back({"thunderstorm_striking",
                  SAMPLE_ASSET_DIR + std::string("/scenes/thunderstorm.json"),
                  std::string(SAMPLE_TEST_DIR) + "/scripts/ground_strikes_every_8_frames.json"});
  runs.push_back(
      {"weather_turning", std::string(SAMPLE_TEST_DIR) + "/scenes/weather_turning.json", ""});
  return runs;
}

void PrintTo(const SceneRun& run, std::ostream* out) {
  *out << run.scene << (run.script.empty() ? "" : " with ") << run.script;
}

std::string sceneRunName(const testing::TestParamInfo<SceneRun>& info) {
  return info.param.name;
}

// One test per scene, so the shards share them out (each run compiles its scene's pipelines).
class EveryScene : public testing::TestWithParam<SceneRun> {};
class EverySceneAndChange : public testing::TestWithParam<SceneRun> {};

// Renders the same HDR frames (every frame, to the bit) with lavapipe on 1 and on 4 threads: no
// pass depends on the order its invocations run in (two runs, so a rerun's differences would
// show too).
TEST_P(EverySceneAndChange, FramesAreTheSameAtAnyThreadCount) {
  const SceneRun& run = GetParam();
  constexpr int kFrames = 10;
  std::vector<std::vector<ImageRgba32f>> captures;
  for (const char* threads : {"1", "4"}) {
    const fs::path dir = freshDir(("threads_" + std::string(threads) + "_" + run.name).c_str());
    const std::string script = run.script.empty() ? "" : " --script " + run.script;
    ASSERT_EQ(std::system((std::string("LP_NUM_THREADS=") + threads + " " + SAMPLE_GAME_EXE +
                           " --headless --frames " + std::to_string(kFrames) +
                           " --fixed-dt 0.0333 --width 160 --height 90 --capture-all --capture " +
                           dir.string() + " --scene " + run.scene + script + " >/dev/null")
                              .c_str()),
              0);
    std::vector<ImageRgba32f> frames;
    for (int f = 0; f < kFrames; ++f) {
      char name[32];
      std::snprintf(name, sizeof(name), "frame_%04d.exr", f);
      frames.push_back(engine::assets::readImage(dir / name));
    }
    captures.push_back(std::move(frames));
  }
  for (int f = 0; f < kFrames; ++f) {
    ASSERT_EQ(captures[1][std::size_t(f)].pixels, captures[0][std::size_t(f)].pixels)
        << "frame " << f << " differs between 1 and 4 threads";
  }
}

INSTANTIATE_TEST_SUITE_P(HeadlessCapture, EverySceneAndChange,
                         testing::ValuesIn(scenesAndChanges()), sceneRunName);

// Paused (a step of 0) and stepped by a microsecond, ten seconds and an hour a frame (the
// clouds' wind, weather and lightning, the time of day and the flight all advance by it), and
// after an uptime of 1e6 s, the scene stays finite, not negative and no brighter than the sun's
// disc (1.6e9 cd/m^2 at noon), under validation.
TEST_P(EveryScene, FramesStayFiniteAtExtremeTimeStepsAndUptime) {
  const SceneRun& run = GetParam();
  for (const char* dt : {"--fixed-dt 0", "--fixed-dt 0.000001", "--fixed-dt 10", "--fixed-dt 3600",
                         "--fixed-dt 0.0333 --start-time 1000000"}) {
    const fs::path dir = freshDir(("extreme_time_step_" + run.name).c_str());
    ASSERT_EQ(runSample("--headless --validation --frames 4 " + std::string(dt) +
                        " --width 96 --height 54 --capture " + dir.string() + " --scene " +
                        run.scene + " >/dev/null 2>&1"),
              0)
        << dt;
    const ImageRgba32f frame = engine::assets::readImage(dir / "frame_0003.exr");
    double sum = 0.0;
    float largest = 0.0f;
    for (float v : frame.pixels) {
      ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << dt << ": " << v;
      sum += v;
      largest = std::max(largest, v);
    }
    EXPECT_LT(largest, 1e10f) << dt;
    EXPECT_GT(sum, 0.0) << dt << ": a black frame";
  }
}

INSTANTIATE_TEST_SUITE_P(HeadlessCapture, EveryScene, testing::ValuesIn(shippedScenes()),
                         sceneRunName);

// The two suites above see the scenes (an empty folder would make them vacuous).
TEST(HeadlessCapture, TheShippedScenesAreFound) {
  ASSERT_GE(shippedScenes().size(), 10u);
}

TEST(HeadlessCapture, EachSceneGetsOnlyThePassesAndPipelinesItNeeds) {
  const auto describe = [](const std::string& scenePath) {
    return runSampleOutput("--headless --describe --width 64 --height 36 --scene " + scenePath);
  };
  struct Case {
    std::string scene;
    std::string passes;
    std::string pipelines;
    std::string modules;
  };
  const Case cases[] = {
      {scene("sky_only.json"), R"("passes": ["sky", "tonemap", "capture"])",
       R"("pipelines": ["tonemap", "sky"])", R"("modules": [])"},
      {scene("terrain_only.json"), R"("passes": ["sky", "terrain", "tonemap", "capture"])",
       R"("pipelines": ["tonemap", "sky", "terrain"])", R"("modules": [], "shadow casters": [])"},
      {scene("clouds_only.json"),
       R"("passes": ["sky", "clouds", "clouds composite", "tonemap", "capture"])",
       R"x("pipelines": ["tonemap", "sky", "clouds module (shadow map)"])x",
       R"("modules": ["clouds"])"},
      // An atmosphere draws the sky in the scene pass: no gradient sky pass or pipeline.
      {scene("atmosphere_only.json"), R"("passes": ["atmosphere", "scene", "tonemap", "capture"])",
       R"("pipelines": ["tonemap", "atmosphere module"])", R"("modules": ["atmosphere"])"},
      // Clouds over terrain shadow it: their shadow map first, the terrain's sunlight read from
      // it, the terrain's shadowed variant.
      {std::string(SAMPLE_ASSET_DIR) + "/scenes/default.json",
       R"("passes": ["cloud shadows", "terrain sunlight", "atmosphere", "scene", "clouds", )"
       R"("clouds composite", "tonemap", "capture"])",
       R"x("pipelines": ["tonemap", "terrain (cloud shadows)", "terrain sunlight", )x"
       R"x("atmosphere module", "clouds module (shadow map, terrain shadow, god rays, sky light)"])x",
       R"("modules": ["atmosphere", "clouds"], "shadow casters": ["clouds", "terrain"])"},
      // God rays: the clouds module's mask and composite variants, no pass of their own.
      {scene("god_rays_sunset.json"),
       R"("passes": ["cloud shadows", "terrain sunlight", "atmosphere", "scene", "clouds", )"
       R"("clouds composite", "tonemap", "capture"])",
       R"x("atmosphere module", "clouds module (shadow map, terrain shadow, god rays, sky light)"])x",
       R"("modules": ["atmosphere", "clouds"])"},
      // A terrain that casts no shadows: the clouds' map alone (the terrain still reads it).
      {scene("ridge_sunset_unshadowing.json"),
       R"("passes": ["cloud shadows", "terrain sunlight", "atmosphere", "scene", "clouds", )"
       R"("clouds composite", "tonemap", "capture"])",
       R"x("pipelines": ["tonemap", "terrain (cloud shadows)", "terrain sunlight", )x"
       R"x("atmosphere module", "clouds module (shadow map, sky light)"])x",
       R"("shadow casters": ["clouds"])"},
      // A storm: the clouds module with its lightning (the glow and the bolts' pass), and the
      // terrain's lightning variant beside its plain one (drawn only while a flash lasts).
      {SAMPLE_ASSET_DIR + std::string("/scenes/thunderstorm.json"),
       R"("passes": ["cloud shadows", "terrain sunlight", "atmosphere", "scene", "clouds", )"
       R"("clouds composite", "tonemap", "capture"])",
       R"x("terrain (cloud shadows)", "terrain (cloud shadows) (lightning)", "terrain sunlight", )x"
       R"x("atmosphere module", "clouds module (shadow map, terrain shadow, god rays, lightning, )x"
       R"x(lightning bolts, sky light)"])x",
       R"("modules": ["atmosphere", "clouds"])"},
      // Hero clouds: the clouds module's hero march (and their atlas), no pass of their own.
      {SAMPLE_ASSET_DIR + std::string("/scenes/hero_clouds.json"),
       R"("passes": ["cloud shadows", "terrain sunlight", "atmosphere", "scene", "clouds", )"
       R"("clouds composite", "tonemap", "capture"])",
       R"x("atmosphere module", "clouds module (shadow map, terrain shadow, hero clouds, sky light)"])x",
       R"("modules": ["atmosphere", "clouds"])"},
      // A lake: the water's pipeline (lit through the terrain's sunlight map), drawn in the
      // scene pass; no pass of its own. The scenes above have no water pipeline.
      {SAMPLE_ASSET_DIR + std::string("/scenes/lake.json"),
       R"("passes": ["cloud shadows", "terrain sunlight", "atmosphere", "scene", "clouds", )"
       R"("clouds composite", "tonemap", "capture"])",
       R"x("pipelines": ["tonemap", "terrain (cloud shadows)", "terrain sunlight", )x"
       R"x("water (cloud shadows)", "atmosphere module", )x"
       R"x("clouds module (shadow map, terrain shadow, god rays, sky light)"])x",
       R"("modules": ["atmosphere", "clouds"])"},
      // A layer that casts no shadows: no shadow pass, the plain terrain.
      {scene("unshadowed_clouds.json"),
       R"("passes": ["sky", "terrain", "clouds", "clouds composite", "tonemap", "capture"])",
       R"("pipelines": ["tonemap", "sky", "terrain", "clouds module"])",
       R"("modules": ["clouds"], "shadow casters": [])"},
  };
  for (const Case& c : cases) {
    const std::string out = describe(c.scene);
    EXPECT_NE(out.find(c.passes), std::string::npos) << c.scene << "\n" << out;
    EXPECT_NE(out.find(c.pipelines), std::string::npos) << c.scene << "\n" << out;
    EXPECT_NE(out.find(c.modules), std::string::npos) << c.scene << "\n" << out;
    // Only a scene with a schedule has weather to run, and with regions regions.
    EXPECT_NE(out.find(R"("weather": [])"), std::string::npos) << c.scene << "\n" << out;
    EXPECT_NE(out.find(R"("weather regions": [])"), std::string::npos) << c.scene << "\n" << out;
  }
  // Changing weather: its schedule, and the default scene's passes, none more.
  const std::string changing =
      describe(std::string(SAMPLE_ASSET_DIR) + "/scenes/changing_weather.json");
  EXPECT_NE(changing.find(R"("weather": ["sparse", "cloudy", "squall", "stormy", "overcast"])"),
            std::string::npos)
      << changing;
  EXPECT_NE(changing.find(R"("weather regions": ["the far ridge", "the superstorm out west"])"),
            std::string::npos)
      << changing;
  EXPECT_NE(changing.find(R"x(lightning bolts, weather regions, superstorm, sky light)")x"),
            std::string::npos)
      << changing;
  // A superstorm: its region, and the vortex code in the clouds module's pipelines; a scene with
  // plain regions has the regions' code and no vortex code (nor have the scenes above).
  const std::string superstorm =
      describe(std::string(SAMPLE_ASSET_DIR) + "/scenes/superstorm.json");
  EXPECT_NE(superstorm.find(R"("weather regions": ["the superstorm"])"), std::string::npos)
      << superstorm;
  EXPECT_NE(superstorm.find(R"x(lightning bolts, weather regions, superstorm, sky light)")x"),
            std::string::npos)
      << superstorm;
  const std::string front = describe(std::string(SAMPLE_ASSET_DIR) + "/scenes/storm_front.json");
  EXPECT_NE(front.find(R"("weather regions": ["front over the range"])"), std::string::npos)
      << front;
  EXPECT_NE(front.find(R"x(, weather regions, sky light)")x"), std::string::npos) << front;
  EXPECT_EQ(front.find("superstorm"), std::string::npos) << front;
  EXPECT_NE(changing.find(R"("passes": ["cloud shadows", "terrain sunlight", "atmosphere", )"
                          R"("scene", "clouds", "clouds composite", "tonemap", "capture"])"),
            std::string::npos)
      << changing;
}

// What a shadow did to a frame: the pixels of `shadowed` darker than `darkerBelow` times their
// luminance in `lit`, and those brighter by over 1%, out of all (0 when the frames differ in
// size).
struct ShadowEffect {
  std::size_t darker = 0;
  std::size_t brighter = 0;
  std::size_t pixels = 0;
};

// Each pixel's luminance (r + g + b) in two captures of one size, row by row: (first, second).
// Empty when their sizes differ.
std::vector<std::pair<float, float>> luminances(const fs::path& first, const fs::path& second) {
  const ImageRgba32f a = engine::assets::readImage(first);
  const ImageRgba32f b = engine::assets::readImage(second);
  std::vector<std::pair<float, float>> pairs;
  if (a.pixels.size() != b.pixels.size()) return pairs;
  pairs.reserve(a.pixels.size() / 4);
  for (std::size_t i = 0; i < a.pixels.size() / 4; ++i) {
    pairs.emplace_back(a.pixels[4 * i] + a.pixels[4 * i + 1] + a.pixels[4 * i + 2],
                       b.pixels[4 * i] + b.pixels[4 * i + 1] + b.pixels[4 * i + 2]);
  }
  return pairs;
}

ShadowEffect shadowEffect(const fs::path& lit, const fs::path& shadowed, float darkerBelow) {
  ShadowEffect e;
  for (const auto& [la, lb] : luminances(lit, shadowed)) {
    e.darker += lb < darkerBelow * la ? 1u : 0u;
    e.brighter += lb > 1.01f * la ? 1u : 0u;
    ++e.pixels;
  }
  return e;
}

// Where the sun is in the god-ray test scenes' 160 x 90 frames (16:30, 55 degrees at noon, the
// camera facing it): straight ahead in azimuth, 4 degrees above the view's 70-degree centre.
const glm::vec2 kSunOnScreen(80.0f, 45.0f - 4.0f / 70.0f * 90.0f);

// A pixel's centre in a 160-pixel-wide frame, from its index.
glm::vec2 pixelCentre(std::size_t i) {
  return {float(i % 160) + 0.5f, float(i / 160) + 0.5f};
}

// Clouds shadow the terrain: seen from above the layer, broken cumulus darkens the ground in
// patches (the direct sun gone, the sky's light left), and nothing else changes.
TEST(HeadlessCapture, CloudsShadowTheTerrainInPatches) {
  const fs::path lit = freshDir("unshadowed");
  const fs::path shadowed = freshDir("shadowed");
  const std::string common =
      "--headless --frames 4 --fixed-dt 0.05 --width 160 --height 90 --validation --capture ";
  ASSERT_EQ(runSample(common + lit.string() + " --scene " + scene("unshadowed_range.json")), 0);
  ASSERT_EQ(runSample(common + shadowed.string() + " --scene " + scene("shadowed_range.json")), 0);
  const ShadowEffect e = shadowEffect(lit / "frame_0003.exr", shadowed / "frame_0003.exr", 0.6f);
  ASSERT_GT(e.pixels, 0u);
  const std::size_t darker = e.darker;
  const std::size_t pixels = e.pixels;
  std::printf("cloud shadows: %.1f%% of pixels 40%% darker, %.2f%% brighter\n",
              100.0 * double(darker) / double(pixels), 100.0 * double(e.brighter) / double(pixels));
  EXPECT_GT(darker, pixels / 20) << "too little of the ground is shadowed";
  EXPECT_LT(darker, pixels * 3 / 4) << "the ground is shadowed everywhere";
  EXPECT_EQ(e.brighter, 0u) << "a shadow only takes light away";
}

// The panel's "cloud shadows" switch (the script sets it as the panel does): off, the ground
// under the clouds is lit as in the scene whose clouds cast none (the module drops its map and
// the terrain's sunlight map is made lit); back on, the shadows return as the map is made again.
TEST(HeadlessCapture, TheShadowSwitchTakesTheCloudShadowsAwayAndBringsThemBack) {
  const fs::path never = freshDir("never_shadowed");
  const fs::path switched = freshDir("shadows_switched");
  fs::create_directories(never);
  fs::create_directories(switched);
  const std::string common =
      "--headless --frames 40 --fixed-dt 0.05 --width 160 --height 90 --validation --capture ";
  const fs::path captures = never / "captures.json";
  std::ofstream(captures) << R"({"events": [{"frame": 6, "capture": "off"},
      {"frame": 38, "capture": "on"}]})";
  const fs::path switches = switched / "switches.json";
  std::ofstream(switches) << R"({"events": [{"frame": 1, "set": {"clouds.shadows": 0}},
      {"frame": 6, "capture": "off"}, {"frame": 8, "set": {"clouds.shadows": 1}},
      {"frame": 38, "capture": "on"}]})";
  ASSERT_EQ(runSample(common + never.string() + " --scene " + scene("unshadowed_range.json") +
                      " --script " + captures.string()),
            0);
  ASSERT_EQ(runSample(common + switched.string() + " --scene " + scene("shadowed_range.json") +
                      " --script " + switches.string()),
            0);
  const ShadowEffect off = shadowEffect(never / "off.exr", switched / "off.exr", 0.6f);
  const ShadowEffect on = shadowEffect(never / "on.exr", switched / "on.exr", 0.6f);
  ASSERT_GT(off.pixels, 0u);
  std::printf("switched off: %zu of %zu pixels 40%% darker; back on: %zu\n", off.darker, off.pixels,
              on.darker);
  EXPECT_LT(off.darker, off.pixels / 200) << "the shadows stayed";
  EXPECT_GT(on.darker, on.pixels / 20) << "the shadows did not come back";
}

// Mountains shade the clouds: at sunset the range's long shadows take the sun from the low
// cumulus behind it (and from the terrain in its lee); nothing gets brighter.
TEST(HeadlessCapture, MountainsShadeTheCloudsAtSunset) {
  const fs::path bare = freshDir("unshadowing_terrain");
  const fs::path shading = freshDir("shading_terrain");
  const std::string common =
      "--headless --frames 6 --fixed-dt 0.05 --width 240 --height 135 --validation --capture ";
  ASSERT_EQ(
      runSample(common + bare.string() + " --scene " + scene("ridge_sunset_unshadowing.json")), 0);
  ASSERT_EQ(runSample(common + shading.string() + " --scene " + scene("ridge_sunset.json")), 0);
  const ShadowEffect e = shadowEffect(bare / "frame_0005.exr", shading / "frame_0005.exr", 0.8f);
  ASSERT_GT(e.pixels, 0u);
  const std::size_t darker = e.darker;
  const std::size_t pixels = e.pixels;
  std::printf("terrain shadows: %.1f%% of pixels 20%% darker, %.2f%% brighter\n",
              100.0 * double(darker) / double(pixels), 100.0 * double(e.brighter) / double(pixels));
  EXPECT_GT(darker, pixels / 100) << "the range's shadows must reach clouds and valleys";
  EXPECT_EQ(e.brighter, 0u) << "a shadow only takes light away";
}

// The range shadows its own valleys at sunset: under a clear sky (the clouds' map holds only
// the terrain's channel) and without an atmosphere (no light shafts), only the terrain's
// lighting through its sunlight map can differ.
TEST(HeadlessCapture, TheRangeShadowsItsOwnValleysAtSunset) {
  const fs::path bare = freshDir("clear_unshadowing_terrain");
  const fs::path shading = freshDir("clear_shading_terrain");
  const std::string common =
      "--headless --frames 3 --fixed-dt 0.05 --width 240 --height 135 --validation --capture ";
  ASSERT_EQ(runSample(common + bare.string() + " --scene " +
                      scene("ridge_sunset_clear_unshadowing.json")),
            0);
  ASSERT_EQ(runSample(common + shading.string() + " --scene " + scene("ridge_sunset_clear.json")),
            0);
  const ShadowEffect e = shadowEffect(bare / "frame_0002.exr", shading / "frame_0002.exr", 0.6f);
  ASSERT_GT(e.pixels, 0u);
  std::printf("the range's own shadows: %.1f%% of pixels 40%% darker, %.2f%% brighter\n",
              100.0 * double(e.darker) / double(e.pixels),
              100.0 * double(e.brighter) / double(e.pixels));
  EXPECT_GT(e.darker, e.pixels / 20) << "the valleys in the range's lee must be shadowed";
  EXPECT_EQ(e.brighter, 0u) << "a shadow only takes light away";
}

// God rays as a mask on the haze: looking towards the afternoon sun through broken cumulus in
// hazy air, the shadows the clouds and mountains cast through the air take some of the haze's
// in-scattering from the sky seen between them (nothing gets brighter, the terrain is left as
// the atmosphere hazed it), and most where the sun's Mie glow is: the light taken lies nearer
// the sun on screen than the sky's pixels do on average.
TEST(HeadlessCapture, GodRaysTakeTheShadowedHazeAwayTowardsTheSun) {
  const fs::path none = freshDir("no_god_rays");
  const fs::path rays = freshDir("god_rays");
  const std::string common =
      "--headless --frames 4 --fixed-dt 0.05 --width 160 --height 90 --validation --capture ";
  ASSERT_EQ(runSample(common + none.string() + " --scene " + scene("god_rays_sunset_none.json")),
            0);
  ASSERT_EQ(runSample(common + rays.string() + " --scene " + scene("god_rays_sunset.json")), 0);
  const auto pairs = luminances(none / "frame_0003.exr", rays / "frame_0003.exr");
  ASSERT_FALSE(pairs.empty());
  std::size_t darker = 0;
  std::size_t brighter = 0;
  std::size_t belowHorizon = 0;
  double lost = 0.0;
  double lostDistance = 0.0;
  double skyDistance = 0.0;
  std::size_t sky = 0;
  const std::size_t pixels = pairs.size();
  for (std::size_t i = 0; i < pixels; ++i) {
    const auto [la, lb] = pairs[i];
    const glm::vec2 p = pixelCentre(i);
    const double distance = glm::length(p - kSunOnScreen);
    if (p.y < 60.0f) {  // above the ridge line
      skyDistance += distance;
      ++sky;
    }
    darker += lb < 0.97f * la ? 1u : 0u;
    belowHorizon += lb < 0.999f * la && p.y > 75.0f ? 1u : 0u;
    brighter += lb > 1.001f * la ? 1u : 0u;
    lost += double(std::max(la - lb, 0.0f));
    lostDistance += double(std::max(la - lb, 0.0f)) * distance;
  }
  ASSERT_GT(lost, 0.0);
  std::printf(
      "god rays: %.1f%% of pixels 3%% darker, %zu brighter, %zu darker on the ground; "
      "light taken %.0f px from the sun on average, the sky's pixels %.0f\n",
      100.0 * double(darker) / double(pixels), brighter, belowHorizon, lostDistance / lost,
      skyDistance / double(sky));
  EXPECT_GT(darker, pixels / 50) << "shafts of shadow in the haze";
  EXPECT_EQ(brighter, 0u) << "a mask only takes light away";
  EXPECT_EQ(belowHorizon, 0u) << "near scenery is left as the atmosphere hazed it";
  EXPECT_LT(lostDistance / lost, 0.9 * skyDistance / double(sky))
      << "the shafts are where the sun's Mie glow is";
}

// Without an atmosphere there is no haze to mask: god rays fall back to a glow along the clear
// paths towards the sun (fxcontracts/god_rays.h), which only adds light, most of it near the sun.
TEST(HeadlessCapture, WithoutHazeGodRaysGlowAroundTheSun) {
  const fs::path none = freshDir("no_glow");
  const fs::path glow = freshDir("glow");
  const std::string common =
      "--headless --frames 4 --fixed-dt 0.05 --width 160 --height 90 --validation --capture ";
  ASSERT_EQ(runSample(common + none.string() + " --scene " + scene("god_rays_no_haze_none.json")),
            0);
  ASSERT_EQ(runSample(common + glow.string() + " --scene " + scene("god_rays_no_haze.json")), 0);
  const auto pairs = luminances(none / "frame_0003.exr", glow / "frame_0003.exr");
  ASSERT_FALSE(pairs.empty());
  std::size_t brighter = 0;
  std::size_t darker = 0;
  double gained = 0.0;
  double gainedDistance = 0.0;
  double allDistance = 0.0;
  const std::size_t pixels = pairs.size();
  for (std::size_t i = 0; i < pixels; ++i) {
    const auto [la, lb] = pairs[i];
    const double distance = glm::length(pixelCentre(i) - kSunOnScreen);
    allDistance += distance;
    brighter += lb > 1.03f * la ? 1u : 0u;
    darker += lb < 0.999f * la ? 1u : 0u;
    gained += double(std::max(lb - la, 0.0f));
    gainedDistance += double(std::max(lb - la, 0.0f)) * distance;
  }
  ASSERT_GT(gained, 0.0);
  std::printf(
      "god rays' glow: %.1f%% of pixels 3%% brighter, %zu darker; light added %.0f px "
      "from the sun on average, all pixels %.0f\n",
      100.0 * double(brighter) / double(pixels), darker, gainedDistance / gained,
      allDistance / double(pixels));
  EXPECT_GT(brighter, pixels / 50);
  EXPECT_EQ(darker, 0u) << "the fallback only adds light";
  EXPECT_LT(gainedDistance / gained, 0.7 * allDistance / double(pixels));
}

// A scripted strike in a storm: while it lasts the clouds around its cell glow and the ground
// below is lit, by the flash and by its sky light (light only added), and half a second after it
// the frame is, to the bit, the frame of the same run without it: the flash left nothing in the
// clouds' histories.
TEST(HeadlessCapture, AScriptedStrikeGlowsAndLeavesNoGhost) {
  const fs::path calm = freshDir("no_strike");
  const fs::path struck = freshDir("strike");
  const std::string common =
      "--headless --fixed-dt 0.0333 --width 160 --height 90 --validation "
      "--scene " +
      scene("storm_calm.json") + " --capture ";
  ASSERT_EQ(runSample(common + calm.string() + " --script " + std::string(SAMPLE_TEST_DIR) +
                      "/scripts/no_strike.json"),
            0);
  ASSERT_EQ(runSample(common + struck.string() + " --script " + std::string(SAMPLE_TEST_DIR) +
                      "/scripts/scripted_strike.json"),
            0);
  const ShadowEffect during = shadowEffect(struck / "during.exr", calm / "during.exr", 1.0f / 1.1f);
  ASSERT_GT(during.pixels, 0u);
  // shadowEffect counts pixels of the second image darker than the first: here the calm run's
  // darker than the struck one's, i.e. the strike's 10% brighter, and the struck ones darker.
  std::printf("scripted strike: %.1f%% of pixels 10%% brighter, %zu darker\n",
              100.0 * double(during.darker) / double(during.pixels), during.brighter);
  EXPECT_GT(during.darker, during.pixels / 50) << "the clouds glow around the strike";
  EXPECT_EQ(during.brighter, 0u) << "a flash only adds light";
  // The flash lights the ground too: the terrain in the lower third gains light, all of it,
  // slopes facing away from the flash included (its sky light; its direct light alone lights
  // less than half of them).
  const auto pairs = luminances(calm / "during.exr", struck / "during.exr");
  std::size_t litGround = 0;
  const std::size_t ground = pairs.size() - pairs.size() * 2 / 3;
  for (std::size_t i = pairs.size() * 2 / 3; i < pairs.size(); ++i) {
    if (pairs[i].second > 1.02f * pairs[i].first) ++litGround;
  }
  std::printf("scripted strike: %zu of %zu ground pixels 2%% brighter\n", litGround, ground);
  EXPECT_GT(litGround, ground * 9 / 10) << "the flash lights the ground from the sky";
  EXPECT_EQ(engine::assets::readImage(struck / "after.exr").pixels,
            engine::assets::readImage(calm / "after.exr").pixels)
      << "no glow left behind";
}

// Painted weather on the schedule: a fair map held for 1 s, blended over 6 s into an overcast
// one, which then holds. The clouds keep their history every frame of it (the map moves by
// less than the history's 1% a frame: a frame that moved it more would have dropped it), the
// frames before and after are those of the fair and the overcast map alone, and the frame
// halfway is neither.
TEST(HeadlessCapture, APaintedMapBlendsIntoTheNextOnTheWeatherSchedule) {
  const fs::path dir = freshDir("painted_schedule");
  fs::create_directories(dir);
  // R coverage, G type, B density, everywhere the same: the noise makes the clouds.
  const auto paint = [&](const char* name, std::uint8_t coverage) {
    engine::assets::ImageRgba8 map{32, 32, {}};
    for (std::size_t i = 0; i < 32 * 32; ++i) {
      map.pixels.insert(map.pixels.end(), {coverage, 128, 255, 255});
    }
    engine::assets::writePng(dir / name, map);
  };
  paint("fair.png", 140);
  paint("overcast.png", 250);
  const std::string start = R"({
    "name": "painted", "camera": {"position": [0, 300, 0], "pitchDegrees": 25},
    "sun": {"timeOfDayHours": 14},
    "exposure": {"mode": "manual", "ev100": 14},)";
  const auto writeScene = [&](const char* name, const std::string& body) {
    std::ofstream(dir / name) << start << body << "}";
    return (dir / name).string();
  };
  const std::string scheduled = writeScene("scheduled.json", R"(
    "clouds": {"weatherMap": "fair.png"},
    "weather": {"states": {"the layer's": {}}, "repeat": false, "schedule": [
      {"state": "the layer's", "holdSeconds": 1, "transitionSeconds": 6},
      {"state": "the layer's", "holdSeconds": 1000, "weatherMap": "overcast.png"}]})");
  const std::string fair = writeScene("fair.json", R"("clouds": {"weatherMap": "fair.png"})");
  const std::string overcast =
      writeScene("overcast.json", R"("clouds": {"weatherMap": "overcast.png"})");
  // Frames at 30 fps: 25 in the fair hold, 120 halfway through the blend, 239 after it.
  std::ofstream(dir / "views.json") << R"({"events": [{"frame": 25, "capture": "before"},
    {"frame": 120, "capture": "middle"}, {"frame": 239, "capture": "after"},
    {"frame": 240, "exit": true}]})";
  const auto run = [&](const std::string& scenePath, const char* out, const char* series) {
    return runSample(
        "--headless --fixed-dt 0.0333333 --width 160 --height 90 --validation "
        "--scene " +
        scenePath + " --script " + (dir / "views.json").string() + " --capture " +
        (dir / out).string() + " --frame-series " + (dir / series).string());
  };
  ASSERT_EQ(run(scheduled, "scheduled", "scheduled.csv"), 0);
  ASSERT_EQ(run(fair, "fair", "fair.csv"), 0);
  ASSERT_EQ(run(overcast, "overcast", "overcast.csv"), 0);

  // The history, frame by frame (the first frame has none to keep).
  const std::vector<std::string> history = readFrameSeries(dir / "scheduled.csv")["clouds_history"];
  for (std::size_t frame = 1; frame < history.size(); ++frame) {
    EXPECT_EQ(history[frame], "reprojected") << "frame " << frame;
  }
  EXPECT_GE(history.size(), 240u);

  // How far apart two captures are: the mean |difference| of their luminances over the mean.
  const auto apart = [&](const fs::path& a, const fs::path& b) {
    double difference = 0.0, sum = 0.0;
    for (const auto& [la, lb] : luminances(a, b)) {
      difference += std::abs(double(la) - lb);
      sum += la;
    }
    return difference / std::max(sum, 1e-9);
  };
  const double maps = apart(dir / "fair" / "after.exr", dir / "overcast" / "after.exr");
  const double before = apart(dir / "scheduled" / "before.exr", dir / "fair" / "before.exr");
  const double after = apart(dir / "scheduled" / "after.exr", dir / "overcast" / "after.exr");
  const double fromFair = apart(dir / "scheduled" / "middle.exr", dir / "fair" / "middle.exr");
  const double fromOvercast =
      apart(dir / "scheduled" / "middle.exr", dir / "overcast" / "middle.exr");
  std::printf(
      "painted schedule: the maps' frames %.3f apart; before %.4f from fair, after %.4f "
      "from overcast; halfway %.3f from fair, %.3f from overcast\n",
      maps, before, after, fromFair, fromOvercast);
  EXPECT_GT(maps, 0.1) << "the two maps make other skies";
  EXPECT_LT(before, 0.01 * maps) << "before the blend: the fair map's frame";
  EXPECT_LT(after, 0.1 * maps) << "after it: the overcast map's";
  EXPECT_GT(fromFair, 0.2 * maps) << "halfway: no longer the fair map's sky";
  EXPECT_GT(fromOvercast, 0.2 * maps) << "halfway: not yet the overcast map's";
}

// How much a pattern of `period` px stands out of an image region: the spread of the means
// over the pixels at each place in the period (content that does not repeat with it averages
// out), over the region's mean.
double periodicPattern(const engine::assets::ImageRgba32f& image, std::uint32_t period,
                       std::uint32_t x0, std::uint32_t y0, std::uint32_t x1, std::uint32_t y1) {
  std::vector<double> sums(std::size_t{period} * period, 0.0);
  std::vector<double> counts(sums.size(), 0.0);
  double total = 0.0;
  for (std::uint32_t y = y0; y < y1; ++y) {
    for (std::uint32_t x = x0; x < x1; ++x) {
      const float* p = image.at(x, y);
      const double value = (p[0] + p[1] + p[2]) / 3.0;
      const std::size_t place = std::size_t{y % period} * period + x % period;
      sums[place] += value;
      counts[place] += 1.0;
      total += value;
    }
  }
  double lo = 1e30;
  double hi = -1e30;
  for (std::size_t i = 0; i < sums.size(); ++i) {
    lo = std::min(lo, sums[i] / counts[i]);
    hi = std::max(hi, sums[i] / counts[i]);
  }
  return (hi - lo) / (total / double(std::size_t{x1 - x0} * (y1 - y0)));
}

// Flying inside a tall layer, looking down through thin cloud at the ground: 1 in 4 trace
// pixels is marched each frame and blended with the reprojected history, and the frame shows
// no pattern of those rays. The haze over the ground is cloud within 300 m of the camera,
// which the rays of a whole region sample at the same places: in Medium's 60 m steps each
// ray's result hinged on where its one sample there fell, and a frame's pattern of start
// offsets showed as a grid of dots (12.5%); with the steps near the camera short (isNearStep
// in cloud_march.h), 9.1%. (Frames rebuilt from their own rays alone,
// with reprojection off inside the layer as before: bilinear between the nearest four, 43%; a
// tent over them, 10 to 11%, but blurred.)
TEST(HeadlessCapture, MovingInsideTheLayerAFrameShowsNoPatternOfItsRays) {
  const fs::path dir = freshDir("inside_the_layer");
  ASSERT_EQ(runSample("--headless --fixed-dt 0.0333 --frames 12 --width 640 --height 360 "
                      "--quality medium --validation --scene " +
                      scene("inside_layer_over_terrain.json") + " --capture " + dir.string()),
            0);
  const engine::assets::ImageRgba32f frame = engine::assets::readImage(dir / "frame_0011.png");
  // The ground seen through thin cloud, lower left; the tent's and the rays' period: 2 x 2
  // rays' start offsets, every second trace pixel, 4 px a trace pixel.
  const double pattern = periodicPattern(frame, 16, 0, 96, 320, 352);
  std::printf("moving inside the layer: a 16 px pattern of %.1f%%\n", 100.0 * pattern);
  EXPECT_LT(pattern, 0.105);
}

// How much of a difference between neighbours (along x, then y; the first difference, or the
// second with `bends`) falls at one place in a period of `period` px: its mean at the place
// where it is largest over its mean anywhere. About 1 without structure of that period.
double periodicShare(const ImageRgba32f& image, std::uint32_t period, bool bends) {
  const auto value = [&](std::uint32_t x, std::uint32_t y) {
    const float* p = image.at(x, y);
    return (p[0] + p[1] + p[2]) / 3.0;
  };
  double worst = 0.0;
  for (std::uint32_t axis = 0; axis < 2; ++axis) {
    const std::uint32_t dx = 1 - axis, dy = axis;
    std::vector<double> sums(period, 0.0), counts(period, 0.0);
    double total = 0.0;
    double count = 0.0;
    for (std::uint32_t y = dy; y + (bends ? dy : 0) < image.height; ++y) {
      for (std::uint32_t x = dx; x + (bends ? dx : 0) < image.width; ++x) {
        const double step = value(x, y) - value(x - dx, y - dy);
        const double difference =
            bends ? std::abs(value(x + dx, y + dy) - value(x, y) - step) : std::abs(step);
        sums[(axis == 0 ? x : y) % period] += difference;
        counts[(axis == 0 ? x : y) % period] += 1.0;
        total += difference;
        count += 1.0;
      }
    }
    for (std::uint32_t i = 0; i < period; ++i)
      worst = std::max(worst, (sums[i] / counts[i]) / std::max(total / count, 1e-12));
  }
  return worst;
}

// How blocky an image is with blocks of `period` px: the share of the steps between neighbours
// at one place in the period. Up to `period` for an image made of blocks.
double blockiness(const ImageRgba32f& image, std::uint32_t period) {
  return periodicShare(image, period, false);
}

// How much an image shows the grid of a coarser image it was upsampled from, every `period` px:
// bilinear upsampling bends the image at each coarse pixel's centre (it does not step), so the
// share of the second differences at one place in the period.
double gridKinks(const ImageRgba32f& image, std::uint32_t period) {
  return periodicShare(image, period, true);
}

// Held inside a cumulus with the ground below seen through it while the wind blows (the
// review set's "inside a cloud"): the history, reprojected and clamped every frame, is
// clamped to a box around each pixel's own estimate. Clamped to the range of the fresh
// samples around it, the same for every pixel of a 4 x 4 tile of the trace, the ground
// turned into blocks of 8 x 8 pixels of one value each: 2.00 by this measure, against 1.51.
// High's near/far split (Settings::nearFieldMetres) marches the cloud within 200 m at every
// pixel of its own image every frame, resolved with each pixel's own 3 x 3 box: 1.30 with it,
// 1.54 with one march, 1.38 with the near field marched but not laid over the far part. What
// is left is the far part's tiles and the pattern of the near field's bilinear upsample of its
// per-pixel noise (the issue's target, 1.1, is not reached).
TEST(HeadlessCapture, HeldInsideACloudTheGroundShowsNoTiles) {
  const fs::path dir = freshDir("inside_a_cloud_held");
  ASSERT_EQ(runSample("--headless --fixed-dt 0.05 --width 640 --height 360 --quality high "
                      "--validation --script " +
                      std::string(SAMPLE_TEST_DIR) + "/scripts/inside_a_cloud_held.json" +
                      " --capture " + dir.string()),
            0);
  const double blocks = blockiness(engine::assets::readImage(dir / "inside_a_cloud.png"), 8);
  std::printf("held inside a cloud: blockiness %.2f\n", blocks);
  EXPECT_LT(blocks, 1.34);
}

// Medium is what players see (issue 53): in the thunderstorm scene at 640x360, after 60 frames
// with the history reprojected, the sky between the clouds must not show as blocks of the trace's
// pixels at every silhouette. A quarter-resolution trace (Medium until the ladder was made, Low
// now) leaves 4 px blocks there; Medium's half-resolution trace with each output pixel's own
// rays is held to High's measure, the same design with a finer march.
TEST(HeadlessCapture, MediumShowsNoBlocksAtTheStormsSilhouettes) {
  const auto blocksAt = [](const char* quality) {
    const fs::path dir = freshDir((std::string("storm_blocks_") + quality).c_str());
    EXPECT_EQ(runSample("--headless --fixed-dt 0.0333 --frames 60 --width 640 --height 360 "
                        "--validation --quality " +
                        std::string(quality) + " --scene " + SAMPLE_ASSET_DIR +
                        "/scenes/thunderstorm.json --capture " + dir.string()),
              0);
    return gridKinks(engine::assets::readImage(dir / "frame_0059.png"), 4);
  };
  const double low = blocksAt("low");
  const double medium = blocksAt("medium");
  const double high = blocksAt("high");
  std::printf("thunderstorm, a 4 px grid: Low %.2f, Medium %.2f, High %.2f\n", low, medium, high);
  EXPECT_LE(medium, high * 1.05);
  EXPECT_GT(low, high * 1.2) << "the measure no longer sees a quarter-resolution trace's grid";
}

// A frame budget in the sample: the governor takes the camera's preset from Medium down to
// Low for an impossible 1 ms a frame and up to Ultra for an easy 10 s, judging the frames'
// wall-clock times; a number key fixes the preset and ends the governing.
TEST(HeadlessCapture, AFrameBudgetChoosesTheCloudPreset) {
  const std::string common =
      "--headless --validation --width 96 --height 54 --fixed-dt 0.05 --frame-target-ms ";
  const std::string low = runSampleCapturing(common + "1 --frames 100", "2>&1");
  EXPECT_NE(low.find("the governor chose Low (1 changes"), std::string::npos) << low;
  const std::string high = runSampleCapturing(common + "10000 --frames 200", "2>&1");
  EXPECT_NE(high.find("the governor chose Ultra (2 changes"), std::string::npos) << high;

  const fs::path dir = freshDir("frame_budget");
  fs::create_directories(dir);
  const fs::path script = dir / "press_3.json";
  std::ofstream(script) << R"({"events": [{"frame": 5, "press": ["3"]},
                                           {"frame": 100, "exit": true}]})";
  const std::string fixed = runSampleCapturing(common + "1 --script " + script.string(), "2>&1");
  EXPECT_EQ(fixed.find("cloud frame budget"), std::string::npos) << fixed;
  EXPECT_NE(fixed.find("frame rate:"), std::string::npos) << fixed;  // it ran
}

// The scene as the player made it (live_settings.h, the settings panel's path; a script's "set"
// here) saves (--save-scene) to a file that renders the very frames the player saw: changed at
// the first frame, captured once the change has settled (a time of day changed in flight takes
// a few frames to reach every cached input), saved, loaded back and captured again: the same
// pixels, where the unchanged scene differs.
TEST(HeadlessCapture, TheSceneAsThePlayerMadeItSavesAndLoadsBackToTheSameFrames) {
  const fs::path dir = freshDir("saved_scene");
  fs::create_directories(dir);
  const auto script = [&](const char* name, const std::string& firstEvents) {
    const fs::path path = dir / name;
    std::ofstream(path)
        << R"({"events": [)" + firstEvents +
               R"({"frame": 60, "capture": "frame"}, {"frame": 60, "exit": true}]})";
    return path.string();
  };
  const std::string changed = script(
      "changed.json", R"({"frame": 0, "set": {"clouds.coverage": 0.62, "sun.timeOfDayHours": 15.25,
                          "clouds.wind.directionDegrees": 33, "exposure.compensationEv": 0.5,
                          "camera.cloudKnobs.lightSteps": 1}},)");
  const std::string plain = script("plain.json", "");
  const std::string common = "--headless --validation --width 96 --height 54 --fixed-dt 0.05 ";
  const fs::path saved = dir / "saved.json";
  ASSERT_EQ(runSample(common + "--script " + changed + " --save-scene " + saved.string() +
                      " --capture " + (dir / "played").string()),
            0);
  ASSERT_EQ(runSample(common + "--script " + plain + " --scene " + saved.string() + " --capture " +
                      (dir / "loaded").string()),
            0);
  ASSERT_EQ(runSample(common + "--script " + plain + " --capture " + (dir / "unchanged").string()),
            0);
  const auto differing = [](const ImageRgba32f& a, const ImageRgba32f& b) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
      count += a.pixels[i] != b.pixels[i] ? 1u : 0u;
    return count + (a.pixels.size() != b.pixels.size() ? 1u : 0u);
  };
  // What the player saw (tonemapped, with its exposure) and the linear radiance.
  for (const char* file : {"frame.png", "frame.exr"}) {
    SCOPED_TRACE(file);
    const ImageRgba32f played = engine::assets::readImage(dir / "played" / file);
    const ImageRgba32f loaded = engine::assets::readImage(dir / "loaded" / file);
    const ImageRgba32f unchanged = engine::assets::readImage(dir / "unchanged" / file);
    EXPECT_EQ(differing(played, loaded), 0u);
    EXPECT_GT(differing(played, unchanged), 1000u);
  }
}

// The HUD in a headless run (--hud-headless): F2 opens the settings panel along the right edge
// below the HUD's line, and changes no other pixel.
TEST(HeadlessCapture, F2OpensTheSettingsPanelAndTouchesNothingElse) {
  const fs::path dir = freshDir("settings_panel");
  fs::create_directories(dir);
  const auto run = [&](const char* name, const char* keys) {
    const fs::path script = dir / (std::string(name) + ".json");
    std::ofstream(script)
        << std::string(R"({"events": [)") + keys +
               R"({"frame": 4, "capture": "frame"}, {"frame": 4, "exit": true}]})";
    EXPECT_EQ(runSample("--headless --validation --hud-headless --width 320 --height 180 "
                        "--fixed-dt 0.05 --script " +
                        script.string() + " --capture " + (dir / name).string()),
              0);
    return engine::assets::readImage(dir / name / "frame.png");
  };
  const ImageRgba32f closed = run("closed", "");
  const ImageRgba32f open = run("open", R"({"frame": 1, "press": ["F2"]}, )");
  ASSERT_EQ(closed.pixels.size(), open.pixels.size());
  double panelChange = 0.0;
  std::size_t elsewhere = 0;
  for (std::uint32_t y = 0; y < closed.height; ++y) {
    for (std::uint32_t x = 0; x < closed.width; ++x) {
      const bool inPanel = x >= closed.width - 306 && y >= 44;
      for (int c = 0; c < 3; ++c) {
        const float d = std::abs(closed.at(x, y)[c] - open.at(x, y)[c]);
        if (inPanel) panelChange += d;
        if (!inPanel && d != 0.0f) ++elsewhere;
      }
    }
  }
  EXPECT_EQ(elsewhere, 0u);
  EXPECT_GT(panelChange / (306.0 * (closed.height - 44) * 3.0), 0.05);  // the panel is there
}

// The HUD's opaque backgrounds, recorded as clears (hud_draw_plan.h), make the pixels ImGui's
// triangles make (to the 8-bit step): the panel open, a section opened by a click, both ways.
TEST(HeadlessCapture, ThePanelsClearsDrawWhatItsTrianglesWould) {
  const fs::path cleared = freshDir("panel_cleared");
  const fs::path drawn = freshDir("panel_drawn");
  fs::create_directories(cleared);
  const fs::path script = cleared / "panel.json";
  std::ofstream(script) << R"({"events": [{"frame": 1, "press": ["F2"]},
      {"frame": 3, "cursor": [500, 199, 1]}, {"frame": 4, "cursor": [500, 199, 0]},
      {"frame": 6, "capture": "frame"}, {"frame": 6, "exit": true}]})";
  const std::string common =
      "--headless --validation --hud-headless --width 640 --height 360 "
      "--fixed-dt 0.05 --script " +
      script.string() + " --capture ";
  ASSERT_EQ(runSample(common + cleared.string()), 0);
  ASSERT_EQ(runSample(common + drawn.string() + " --hud-as-triangles"), 0);
  const ImageRgba32f a = engine::assets::readImage(cleared / "frame.png");
  const ImageRgba32f b = engine::assets::readImage(drawn / "frame.png");
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  // The clear writes the vertices' colour exactly; the triangles interpolate it, in floating
  // point: a value at an 8-bit rounding boundary may land one step away, never more.
  float largest = 0.0f;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    largest = std::max(largest, std::abs(a.pixels[i] - b.pixels[i]));
    differing += a.pixels[i] != b.pixels[i];
  }
  std::printf("%zu of %zu values differ, by at most %.1f/255\n", differing, a.pixels.size(),
              double(largest) * 255.0);
  EXPECT_LE(largest, 1.01f / 255.0f);
}

// The panel driven by the mouse, as a player does (the script's "cursor": the free cursor and
// its button): F2, a click on the "cloud preset's knobs" header, a click at the left end of
// the "light samples" slider. The clouds lose their self-shadowing (0 light samples: the sky
// left of the panel changes) and the saved scene says so. The positions are the panel's at
// 640x360 (tools/panel_picture.sh shows it); a layout change that moves them fails here.
TEST(HeadlessCapture, TheMouseDrivesThePanelsSliders) {
  const fs::path dir = freshDir("panel_mouse");
  fs::create_directories(dir);
  const auto run = [&](const char* name, const char* clicks) {
    const fs::path script = dir / (std::string(name) + ".json");
    std::ofstream(script)
        << std::string(R"({"events": [{"frame": 1, "press": ["F2"]}, )") + clicks +
               R"({"frame": 12, "capture": "frame"}, {"frame": 12, "exit": true}]})";
    EXPECT_EQ(runSample("--headless --validation --hud-headless --width 640 --height 360 "
                        "--fixed-dt 0.05 --script " +
                        script.string() + " --capture " + (dir / name).string() + " --save-scene " +
                        (dir / name / "saved.json").string()),
              0);
    return engine::assets::readImage(dir / name / "frame.exr");
  };
  const ImageRgba32f still = run("still", "");
  const ImageRgba32f clicked = run("clicked", R"({"frame": 3, "cursor": [500, 199, 1]},
    {"frame": 4, "cursor": [500, 199, 0]}, {"frame": 6, "cursor": [394, 268, 1]},
    {"frame": 7, "cursor": [394, 268, 0]}, )");
  ASSERT_EQ(still.pixels.size(), clicked.pixels.size());
  std::size_t changed = 0;  // pixels left of the panel
  for (std::uint32_t y = 0; y < still.height; ++y) {
    for (std::uint32_t x = 0; x < 380; ++x) {
      if (std::abs(still.at(x, y)[0] - clicked.at(x, y)[0]) > 0.01f * still.at(x, y)[0]) ++changed;
    }
  }
  std::printf("left of the panel, %zu pixels changed by the click\n", changed);
  EXPECT_GT(changed, 2000u);
  const nlohmann::json saved = engine::JsonReader::parseFile(dir / "clicked" / "saved.json");
  EXPECT_EQ(saved["camera"]["cloudKnobs"].dump(), R"({"lightSteps":0})");
  EXPECT_FALSE(
      engine::JsonReader::parseFile(dir / "still" / "saved.json")["camera"].contains("cloudKnobs"));
}

// Editing the scene file while the sample runs: a file that does not load is reported and the
// running scene kept; one that loads is applied where it can be live (a thinner cover, here),
// and what needs a restart (the terrain's shadows) is said to. Each edit is written (whole,
// by a rename) once the sample has logged what the one before did.
TEST(HeadlessCapture, EditingTheSceneFileWhileItRunsAppliesIt) {
  const fs::path dir = freshDir("hot_reload");
  fs::create_directories(dir);
  const fs::path scene = dir / "scene.json";
  std::string text = shippedSceneText("default.json");
  std::ofstream(scene) << text;
  const auto rewrite = [&](const std::string& content) {
    std::ofstream(dir / "next.json") << content;
    fs::rename(dir / "next.json", scene);
  };
  // `text` with `from` replaced by `to`, kept as the text the next edit starts from.
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string& edited = text;
    const std::size_t at = edited.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) edited.replace(at, from.size(), to);
    return edited;
  };
  const std::string common = "--headless --validation --width 96 --height 54 --fixed-dt 0.05 ";
  const std::string command = std::string(SAMPLE_GAME_EXE) + " " + common +
                              "--frames 900 --scene " + scene.string() + " --capture " +
                              (dir / "edited").string() + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  ASSERT_TRUE(pipe);
  std::string log;
  int step = 0;
  std::array<char, 1024> line{};
  while (std::fgets(line.data(), line.size(), pipe.get()) != nullptr) {
    const std::string l = line.data();
    log += l;
    if (step == 0 && l.find("pipelines warmed up") != std::string::npos) {
      rewrite("{ \"name\": ");  // not JSON
      step = 1;
    } else if (step == 1 && l.find("scene not reloaded") != std::string::npos) {
      rewrite(replaced("\"coverage\": 0.6", "\"coverage\": 0.25"));
      step = 2;
    } else if (step == 2 && l.find("scene reloaded") != std::string::npos) {
      rewrite(replaced("\"gltf\": \"default\"", "\"gltf\": \"default\", \"castsShadows\": false"));
      step = 3;
    }
  }
  pipe.reset();
  EXPECT_NE(log.find("scene not reloaded: " + scene.string()), std::string::npos) << log;
  EXPECT_NE(log.find("(the running scene is kept)"), std::string::npos) << log;
  EXPECT_NE(log.find("scene reloaded: scene.json: applied\n"), std::string::npos) << log;
  EXPECT_NE(log.find("scene reloaded: scene.json: applied; other changes"), std::string::npos)
      << log;

  ASSERT_EQ(runSample(common + "--frames 900 --scene " +
                      (fs::path(SAMPLE_ASSET_DIR) / "scenes" / "default.json").string() +
                      " --capture " + (dir / "unedited").string()),
            0);
  const ImageRgba32f edited = engine::assets::readImage(dir / "edited" / "frame_0899.exr");
  const ImageRgba32f unedited = engine::assets::readImage(dir / "unedited" / "frame_0899.exr");
  // The thinner cover lets more of the sky and the ground through: the clouds' transmittance
  // is folded into the picture, so compare the sky's part above the horizon, the top third.
  double change = 0.0;
  for (std::uint32_t y = 0; y < edited.height / 3; ++y)
    for (std::uint32_t x = 0; x < edited.width; ++x)
      change += std::abs(edited.at(x, y)[1] - unedited.at(x, y)[1]);
  std::printf("the sky after the edit: %.4f mean change\n",
              change / (edited.width * (edited.height / 3)));
  EXPECT_GT(change / (edited.width * (edited.height / 3)), 1.0);  // 0.000 without the edit
}

TEST(HeadlessCapture, FliesOverAUserSuppliedTerrain) {
  const fs::path dir = freshDir("user_terrain");
  ASSERT_EQ(runSample("--headless --frames 1 --width 96 --height 54 --validation --terrain " +
                      std::string(HILLS_TERRAIN) + " --scene " + scene("terrain_only.json") +
                      " --capture " + dir.string()),
            0);
  EXPECT_TRUE(fs::exists(dir / "frame_0000.png"));
}

// A user's OpenVDB cloud (--cloud) stands in front of the camera's start: the frame's middle
// holds it, where the same scene without it shows the sky; a scene saved from that run keeps it
// where it stood (the same frames loaded back). A missing or broken file is refused naming it.
TEST(HeadlessCapture, ShowsAUserSuppliedVdbCloudAhead) {
  const fs::path dir = freshDir("user_cloud");
  fs::create_directories(dir);
  const fs::path vdb = dir / "puff.vdb";
  // A ball of smoke 400 m across, in 10 m voxels.
  vdb_test::write(vdb, {vdb_test::floatGrid("density", 10.0, {0.0, 0.0, 0.0}, openvdb::Coord(0),
                                            openvdb::Coord(39), [](openvdb::Coord c) {
                                              const double r = glm::length(
                                                  glm::dvec3(c.x(), c.y(), c.z()) - 19.5);
                                              return float(std::clamp(1.0 - r / 18.0, 0.0, 1.0));
                                            })});
  const std::string common =
      "--headless --frames 3 --width 96 --height 54 --validation --fixed-dt 0.05 --scene " +
      scene("clouds_only.json") + " --capture ";
  ASSERT_EQ(runSample(common + (dir / "sky").string()), 0);
  const fs::path saved = dir / "saved.json";
  ASSERT_EQ(runSample(common + (dir / "cloud").string() + " --cloud " + vdb.string() +
                      " --save-scene " + saved.string()),
            0);
  const ImageRgba32f sky = engine::assets::readImage(dir / "sky" / "frame_0002.exr");
  const ImageRgba32f cloud = engine::assets::readImage(dir / "cloud" / "frame_0002.exr");
  ASSERT_EQ(runSample("--headless --frames 3 --width 96 --height 54 --validation --fixed-dt 0.05 "
                      "--scene " +
                      saved.string() + " --capture " + (dir / "saved").string()),
            0);
  EXPECT_TRUE(engine::assets::readImage(dir / "saved" / "frame_0002.exr").pixels == cloud.pixels)
      << "the saved scene lost the user's cloud or moved it";
  ASSERT_EQ(sky.pixels.size(), cloud.pixels.size());
  const float* a = sky.at(48, 27);
  const float* b = cloud.at(48, 27);
  const float skyMiddle = a[0] + a[1] + a[2];
  const float cloudMiddle = b[0] + b[1] + b[2];
  std::printf("the frame's middle: sky %.3g, cloud %.3g\n", skyMiddle, cloudMiddle);
  EXPECT_GT(std::abs(cloudMiddle - skyMiddle), 0.2f * skyMiddle);

  EXPECT_NE(runSampleErrors("--headless --frames 1 --cloud /no/such/cloud.vdb")
                .find("/no/such/cloud.vdb: no such file"),
            std::string::npos);
  const fs::path broken = dir / "broken.vdb";
  std::ofstream(broken) << "not a volume";
  EXPECT_NE(runSampleErrors("--headless --frames 1 --cloud " + broken.string())
                .find(broken.string() + ": not a readable OpenVDB file"),
            std::string::npos);
}

// Runs a shipped scene (assets_src/scenes) at 30 fps, 160 x 90, with its frame series, and
// returns the series' exposure columns: what the meter read and what the frame was shown with.
struct ExposureSeries {
  std::vector<double> metered;
  std::vector<double> shown;
};
ExposureSeries flyForExposure(const fs::path& dir, const std::string& scenePath,
                              const std::string& extra) {
  fs::create_directories(dir);
  const fs::path series = dir / "series.csv";
  EXPECT_EQ(runSample("--headless --fixed-dt 0.0333333 --width 160 --height 90 --scene " +
                      scenePath + " --frame-series " + series.string() + " " + extra),
            0);
  auto columns = readFrameSeries(series);
  return {numbers(columns["metered_ev100"]), numbers(columns["ev100"])};
}

// Exposure that meters the clouds (game/exposure_control.h): the overcast scene, which was once
// hand-exposed a stop brighter than the clear sky's meter read, needs no compensation. Its first
// frame is metered before the clouds measured their sky, as the clear sky's meter reads it; from
// then on the meter reads the overcast (the sky light under it and the sun through it at the
// camera) and the exposure settles on that. Both readings are those of the photographers'
// sunny-16 rule, EV100 = log2(N^2 x 100) at f/N: f/16 in sun (14.64), f/8 under an overcast
// (12.64), each within 1 EV; the clear sky's meter is over 2 EV from the overcast's.
TEST(HeadlessCapture, AnOvercastIsExposedForItsCloudsWithoutCompensation) {
  const double sunny16 = std::log2(16.0 * 16.0 * 100.0);
  const double overcastF8 = std::log2(8.0 * 8.0 * 100.0);
  const std::string overcast = std::string(SAMPLE_ASSET_DIR) + "/scenes/overcast_stratus.json";
  const ExposureSeries ev = flyForExposure(freshDir("overcast_exposure"), overcast, "--frames 90");
  ASSERT_EQ(ev.metered.size(), 90u);
  const double clearReading = ev.metered.front();
  std::printf(
      "overcast: the clear sky meters EV100 %.2f (sunny 16: %.2f), the clouds %.2f "
      "(overcast, f/8: %.2f); shown at %.2f after 3 s\n",
      clearReading, sunny16, ev.metered.back(), overcastF8, ev.shown.back());
  EXPECT_NEAR(clearReading, sunny16, 1.0) << "the clear sky's meter, before the clouds' sky";
  EXPECT_NEAR(ev.metered.back(), overcastF8, 1.0) << "the meter reads the overcast";
  EXPECT_GT(std::abs(clearReading - overcastF8), 2.0) << "which the clear sky's meter does not";
  EXPECT_NEAR(ev.shown.back(), ev.metered.back(), 0.2) << "the exposure follows the meter";
}

// Under a clear sky the clouds' sky light is the clear sky's (engine::render::CoveredSkyLight
// against SkyLight): the default scene without clouds (coverage 0), run with the clouds' sky
// light and without it, meters the same exposure and lights every pixel of the ground the same,
// each to a stated tolerance (the covered sky is a 64 x 32 half-float map of the sky the
// atmosphere measures its SkyLight from). Measured: 0.03 EV apart (the clear sky's meter
// estimates its irradiance from SkyLight's regions, the clouds' integrate their map), pixels
// at most 0.2% apart; with the covered horizon 10% too bright (tried once), pixels up to 4.9%.
TEST(HeadlessCapture, UnderAClearSkyTheCloudsSkyLightIsTheClearSkys) {
  constexpr double kMaxEvDifference = 0.05;
  constexpr double kMaxPixelDifference = 0.01;  // relative, in the scene-referred capture
  const fs::path dir = freshDir("clear_sky_light");
  fs::create_directories(dir);
  const std::string text = shippedSceneText("default.json");
  const std::string coverage = R"("coverage": 0.6)";
  ASSERT_NE(text.find(coverage), std::string::npos);
  std::map<bool, ExposureSeries> series;
  for (const bool skyLight : {true, false}) {
    std::string edited = text;
    edited.replace(edited.find(coverage), coverage.size(),
                   std::string(R"("coverage": 0, "skyLight": )") + (skyLight ? "true" : "false"));
    const fs::path run = dir / (skyLight ? "with" : "without");
    fs::create_directories(run);
    std::ofstream(run / "scene.json") << edited;
    series[skyLight] = flyForExposure(run, (run / "scene.json").string(),
                                      "--frames 30 --validation --capture " + run.string());
    ASSERT_EQ(series[skyLight].metered.size(), 30u);
  }
  double largest = 0.0;
  std::size_t pixels = 0;
  for (const auto& [a, b] :
       luminances(dir / "with" / "frame_0029.exr", dir / "without" / "frame_0029.exr")) {
    ASSERT_GT(b, 0.0f);
    largest = std::max(largest, std::abs(double(a) / double(b) - 1.0));
    ++pixels;
  }
  ASSERT_EQ(pixels, 160u * 90u);
  const double evDifference = series[true].metered.back() - series[false].metered.back();
  std::printf(
      "clear sky: metered EV100 %.3f with the clouds' sky light, %.3f without; pixels at most "
      "%.4f apart\n",
      series[true].metered.back(), series[false].metered.back(), largest);
  EXPECT_LE(std::abs(evDifference), kMaxEvDifference);
  EXPECT_LE(largest, kMaxPixelDifference);
}

// Under broken cloud the meter reads the sun through the clouds at the camera, so a flight in
// and out of their shadows moves the exposure, and the adaptation's time constant (0.5 s) keeps
// it from flickering: over 10 s at 30 fps, flying at 300 m/s through the noon cumulus' shadows,
// the meter swings by over a stop, and the exposure moves by no more than kMaxStepEv from one
// frame to the next (1.5 EV a second: a third of a stop, a step the eye sees, takes at least 7
// frames). The same flight adapted at once (time constant 0) steps by more: the bound can fail.
TEST(HeadlessCapture, ExposureFollowsCloudShadowsWithoutFlicker) {
  constexpr double kMaxStepEv = 0.05;
  const fs::path dir = freshDir("exposure_flight");
  fs::create_directories(dir);
  const std::string text = shippedSceneText("cumulus_noon.json");
  const std::string at = R"("mode": "auto")";
  ASSERT_NE(text.find(at), std::string::npos);
  for (const double tau : {0.5, 0.0}) {
    std::string edited = text;
    edited.replace(edited.find(at), at.size(),
                   at + ", \"adaptationSeconds\": " + std::to_string(tau));
    const fs::path scenePath = dir / ("cumulus_tau" + std::to_string(int(tau * 10)) + ".json");
    std::ofstream(scenePath) << edited;
    const ExposureSeries ev = flyForExposure(
        dir / scenePath.stem(), scenePath.string(),
        "--frames 300 --script " + std::string(SAMPLE_TEST_DIR) + "/scripts/shadow_flight.json");
    ASSERT_EQ(ev.shown.size(), 300u);
    // After the clouds' first measured sky (it comes from a completed frame, the third here; the
    // meter's first readings, the clear sky's and then the first with the clouds, are each taken
    // at once).
    double lowest = 1e9, highest = -1e9, largestStep = 0.0;
    for (std::size_t frame = 5; frame < ev.shown.size(); ++frame) {
      lowest = std::min(lowest, ev.metered[frame]);
      highest = std::max(highest, ev.metered[frame]);
      largestStep = std::max(largestStep, std::abs(ev.shown[frame] - ev.shown[frame - 1]));
    }
    std::printf(
        "time constant %.1f s: the meter read EV100 %.2f to %.2f, the largest step a frame "
        "%.3f EV\n",
        tau, lowest, highest, largestStep);
    EXPECT_GT(highest - lowest, 1.0) << "the flight crossed the clouds' shadows";
    if (tau > 0.0) {
      EXPECT_LE(largestStep, kMaxStepEv) << "no flicker";
    } else {
      EXPECT_GT(largestStep, kMaxStepEv) << "the negative control: adapted at once, it steps";
    }
  }
}

TEST(HeadlessCapture, BadArgumentsAndScenesFailWithAMessage) {
  EXPECT_NE(runSample("--headless --width 0 2>/dev/null"), 0);
  EXPECT_NE(runSample("--headless --frames banana 2>/dev/null"), 0);
  EXPECT_NE(runSample("--no-such-option 2>/dev/null"), 0);
  EXPECT_NE(runSample("--headless --quality extreme 2>/dev/null"), 0);
  EXPECT_EQ(runSample("--headless --scene /no/such/scene.json 2>/dev/null"), 1);
  EXPECT_EQ(runSample("--headless --terrain /no/such/terrain.glb 2>/dev/null"), 1);
  EXPECT_EQ(runSample("--headless --script /no/such/script.json 2>/dev/null"), 1);
}

// Each numeric option just outside its documented range (options.cpp, the README's table of
// validated input), and NaN, is refused before anything runs, by a message naming the option.
TEST(HeadlessCapture, EveryOptionOutsideItsRangeIsRefusedNamingIt) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--width", "15"},       {"--width", "7681"},      {"--height", "15"},
      {"--height", "4321"},    {"--frames", "-1"},       {"--frames", "1000001"},
      {"--fixed-dt", "-0.01"}, {"--fixed-dt", "3600.5"}, {"--fixed-dt", "nan"},
      {"--fixed-dt", "inf"},   {"--start-time", "-1"},   {"--start-time", "1.1e9"},
      {"--start-time", "nan"}, {"--quality", "best"}};
  for (const auto& [option, value] : cases) {
    const std::string arguments = "--headless " + option + " " + value;
    EXPECT_NE(runSample(arguments + " >/dev/null 2>&1"), 0) << arguments;
    EXPECT_NE(runSampleErrors(arguments).find(option + ":"), std::string::npos) << arguments;
  }
}

}  // namespace
