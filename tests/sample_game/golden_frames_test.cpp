// Golden frames: the sample renders small views headless from scripts (ground view of clouds
// over mountains, terrain hiding clouds, a cloud in front of a mountain, above the layer,
// inside a cloud, noon, sunset, cumulus overhead, towards the sun, an overcast stratus deck,
// a ridge shading clouds at sunset, cloud shadows on the plains at noon, flying inside the
// layer at High and Medium, hero clouds outside, inside, at sunset and in a storm, the default
// view under each built-in weather state, a storm front over the range, a lake and water sorting
// with clouds: the review
// set's views among them) and each is compared with its
// committed golden image by the tolerance tree in golden_compare.h. Every run writes the actual
// images to build/golden_output/ (what tools/promote_goldens.sh copies into tests/goldens/); a
// failing view also gets <name>_actual/_expected/_diff.png in build/golden_failures/.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "engine/assets/image_io.h"
#include "engine/core/json_reader.h"
#include "golden_compare.h"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> captureNames(const fs::path& script) {
  const nlohmann::json json = engine::JsonReader::parseFile(script);
  std::vector<std::string> names;
  for (const auto& e : json.at("events")) {
    if (e.contains("capture")) names.push_back(e.at("capture").get<std::string>());
  }
  return names;
}

// A scene, the script that takes the sample through its golden views, and the clouds' preset.
struct GoldenRun {
  fs::path scene;
  fs::path script;
  const char* quality = "high";
};

std::vector<GoldenRun> goldenRuns() {
  const fs::path tests = SAMPLE_TEST_DIR;
  return {
      // Clouds over mountains, occlusion both ways, above and inside the layer, noon, sunset,
      // cumulus overhead and towards the sun.
      {tests / "scenes/golden.json", tests / "scripts/golden_views.json"},
      // A stratus deck (the project's overcast scene, as the review set shows it).
      {fs::path(SAMPLE_ASSET_DIR) / "scenes/overcast_stratus.json",
       tests / "scripts/golden_overcast_views.json"},
      // Long shadows both ways: the range's on low cumulus at sunset, the clouds' on the
      // plains at noon.
      {tests / "scenes/ridge_sunset.json", tests / "scripts/golden_shadow_views.json"},
      // A scripted lightning strike glowing in a storm's clouds.
      {tests / "scenes/storm_calm.json", tests / "scripts/golden_strike_views.json"},
      // The thunderstorm scene (cells from the weather, dense cumulonimbus at dusk) with a
      // scripted ground strike: its bolt, its glow and the ground it lights.
      {fs::path(SAMPLE_ASSET_DIR) / "scenes/thunderstorm.json",
       tests / "scripts/golden_thunderstorm_views.json"},
      // Hero clouds (the voxel clouds): outside at noon, inside one, at sunset, and the
      // cumulonimbus at dusk, calm and lit by a scripted strike.
      {tests / "scenes/hero_golden.json", tests / "scripts/golden_hero_views.json"},
      // The default view under each built-in weather state (the storm's between strikes),
      // switched at once, 23 frames each.
      {tests / "scenes/weather_states.json", tests / "scripts/golden_weather_views.json"},
      // A storm front (a weather region) over the range in fair weather: from the plains, and
      // under it.
      {tests / "scenes/weather_front.json", tests / "scripts/golden_front_views.json"},
      // A superstorm (a weather region with a vortex) over the range: from outside its eye
      // wall, and from above its bands.
      {tests / "scenes/superstorm.json", tests / "scripts/golden_superstorm_views.json"},
      // Water: the shipped lake reflecting the cloudy sky, and the water sorting with clouds
      // (a small cloud over a deep lake composited over it, one under its surface hidden).
      {fs::path(SAMPLE_ASSET_DIR) / "scenes/lake.json", tests / "scripts/golden_lake_views.json"},
      {tests / "scenes/water_sorting.json", tests / "scripts/golden_water_sorting_views.json"},
      // Flying inside a tall layer over the ground, at High and Medium: frames rebuilt from
      // their own rays, without a pattern of them.
      {tests / "scenes/inside_layer_over_terrain.json",
       tests / "scripts/golden_inside_layer_high.json", "high"},
      {tests / "scenes/inside_layer_over_terrain.json",
       tests / "scripts/golden_inside_layer_medium.json", "medium"},
  };
}

TEST(GoldenFrames, ScriptedViewsMatchTheirGoldens) {
  const fs::path output = GOLDEN_OUTPUT_DIR;
  const fs::path failures = GOLDEN_FAILURE_DIR;
  fs::remove_all(output);
  fs::remove_all(failures);
  std::vector<std::string> names;
  for (const GoldenRun& run : goldenRuns()) {
    const std::string command = std::string(SAMPLE_GAME_EXE) +
                                " --headless --validation --width 256 --height 144 --fixed-dt 0.05"
                                " --quality " +
                                run.quality + " --scene " + run.scene.string() + " --script " +
                                run.script.string() + " --capture " + output.string();
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    for (std::string& name : captureNames(run.script)) names.push_back(std::move(name));
  }

  const test::GoldenTolerance tolerance;
  ASSERT_GE(names.size(), 10u);
  for (const std::string& name : names) {
    const fs::path actualPath = output / (name + ".png");
    const fs::path goldenPath = fs::path(GOLDEN_DIR) / (name + ".png");
    ASSERT_TRUE(fs::exists(actualPath)) << "the run did not capture " << name;
    if (!fs::exists(goldenPath)) {
      ADD_FAILURE() << "no golden for " << name << ": review " << actualPath
                    << " and promote it with tools/promote_goldens.sh";
      continue;
    }
    const auto actual = engine::assets::readImage(actualPath);
    const auto expected = engine::assets::readImage(goldenPath);
    const test::GoldenResult result = test::compareImages(actual, expected, tolerance);
    if (!result.passed(tolerance)) {
      fs::create_directories(failures);
      fs::copy_file(actualPath, failures / (name + "_actual.png"),
                    fs::copy_options::overwrite_existing);
      fs::copy_file(goldenPath, failures / (name + "_expected.png"),
                    fs::copy_options::overwrite_existing);
      engine::assets::writePng(failures / (name + "_diff.png"),
                               test::diffImage(actual, expected, tolerance));
      ADD_FAILURE() << name << ": " << result.describe() << "\n  actual   "
                    << failures / (name + "_actual.png") << "\n  expected "
                    << failures / (name + "_expected.png") << "\n  diff     "
                    << failures / (name + "_diff.png");
    }
  }
}

TEST(GoldenFrames, TheComparisonCatchesAChangedImage) {
  // Negative control for the tolerance tree: a small bright square (0.4% of the pixels) passes,
  // a larger one fails, and a global shift below the pixel threshold still passes.
  engine::assets::ImageRgba32f a{64, 36, std::vector<float>(64 * 36 * 4, 0.5f)};
  engine::assets::ImageRgba32f b = a;
  const test::GoldenTolerance t;
  for (std::uint32_t y = 0; y < 3; ++y) {
    for (std::uint32_t x = 0; x < 3; ++x) b.at(x, y)[0] = 1.0f;
  }
  EXPECT_TRUE(test::compareImages(b, a, t).passed(t)) << test::compareImages(b, a, t).describe();
  for (std::uint32_t y = 0; y < 10; ++y) {
    for (std::uint32_t x = 0; x < 10; ++x) b.at(x, y)[0] = 1.0f;
  }
  EXPECT_FALSE(test::compareImages(b, a, t).passed(t));
  engine::assets::ImageRgba32f shifted = a;
  for (float& v : shifted.pixels) v += 2.0f / 255.0f;
  EXPECT_TRUE(test::compareImages(shifted, a, t).passed(t));
  engine::assets::ImageRgba32f smaller{32, 36, std::vector<float>(32 * 36 * 4, 0.5f)};
  EXPECT_FALSE(test::compareImages(smaller, a, t).passed(t));
}

}  // namespace
