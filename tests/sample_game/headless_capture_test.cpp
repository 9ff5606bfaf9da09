// Runs the sample binary headless, as a user would, and checks what it writes: the exit code
// (non-zero on any validation message), image sizes and content (sky above, terrain below,
// clouds, HDR in the EXR, nothing non-finite), determinism, the pass list each kind of scene
// gets, flying over a user's glTF, and clear failures for bad arguments and scenes.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "engine/assets/image_io.h"

namespace {

namespace fs = std::filesystem;
using engine::assets::ImageRgba32f;

int runSample(const std::string& arguments) {
  const std::string command = std::string(SAMPLE_GAME_EXE) + " " + arguments;
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string runSampleOutput(const std::string& arguments) {
  const std::string command = std::string(SAMPLE_GAME_EXE) + " " + arguments + " 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 512> buffer{};
  while (pipe && std::fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr)
    out += buffer.data();
  return out;
}

fs::path freshDir(const char* name) {
  const fs::path dir = fs::temp_directory_path() / "cloudscape_sample_tests" / name;
  fs::remove_all(dir);
  return dir;
}

std::string scene(const char* name) {
  return std::string(SAMPLE_TEST_DIR) + "/scenes/" + name;
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

TEST(HeadlessCapture, EachSceneGetsOnlyThePassesAndPipelinesItNeeds) {
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
       R"("pipelines": ["tonemap", "sky", "clouds module"])", R"("modules": ["clouds"])"},
      // An atmosphere draws the sky in the scene pass: no gradient sky pass or pipeline.
      {scene("atmosphere_only.json"), R"("passes": ["atmosphere", "scene", "tonemap", "capture"])",
       R"("pipelines": ["tonemap", "atmosphere module"])", R"("modules": ["atmosphere"])"},
      // Clouds over terrain shadow it: their shadow map first, the terrain's sunlight read from
      // it, the terrain's shadowed variant.
      {std::string(SAMPLE_ASSET_DIR) + "/scenes/default.json",
       R"("passes": ["cloud shadows", "terrain sunlight", "atmosphere", "scene", "clouds", )"
       R"("clouds composite", "tonemap", "capture"])",
       R"x("pipelines": ["tonemap", "terrain (cloud shadows)", "terrain sunlight", )x"
       R"x("atmosphere module", "clouds module"])x",
       R"("modules": ["atmosphere", "clouds"], "shadow casters": ["clouds", "terrain"])"},
      // A terrain that casts no shadows: the clouds' map alone (the terrain still reads it).
      {scene("ridge_sunset_unshadowing.json"),
       R"("passes": ["cloud shadows", "terrain sunlight", "atmosphere", "scene", "clouds", )"
       R"("clouds composite", "tonemap", "capture"])",
       R"x("pipelines": ["tonemap", "terrain (cloud shadows)", "terrain sunlight", )x"
       R"x("atmosphere module", "clouds module"])x",
       R"("shadow casters": ["clouds"])"},
      // A layer that casts no shadows: no shadow pass, the plain terrain.
      {scene("unshadowed_clouds.json"),
       R"("passes": ["sky", "terrain", "clouds", "clouds composite", "tonemap", "capture"])",
       R"("pipelines": ["tonemap", "sky", "terrain", "clouds module"])",
       R"("modules": ["clouds"], "shadow casters": [])"},
  };
  for (const Case& c : cases) {
    const std::string out =
        runSampleOutput("--headless --describe --width 64 --height 36 --scene " + c.scene);
    EXPECT_NE(out.find(c.passes), std::string::npos) << c.scene << "\n" << out;
    EXPECT_NE(out.find(c.pipelines), std::string::npos) << c.scene << "\n" << out;
    EXPECT_NE(out.find(c.modules), std::string::npos) << c.scene << "\n" << out;
  }
}

// What a shadow did to a frame: the pixels of `shadowed` darker than `darkerBelow` times their
// luminance in `lit`, and those brighter by over 1%, out of all (0 when the frames differ in
// size).
struct ShadowEffect {
  std::size_t darker = 0;
  std::size_t brighter = 0;
  std::size_t pixels = 0;
};

ShadowEffect shadowEffect(const fs::path& lit, const fs::path& shadowed, float darkerBelow) {
  const ImageRgba32f a = engine::assets::readImage(lit);
  const ImageRgba32f b = engine::assets::readImage(shadowed);
  ShadowEffect e;
  if (a.pixels.size() != b.pixels.size()) return e;
  e.pixels = a.pixels.size() / 4;
  for (std::size_t i = 0; i < e.pixels; ++i) {
    const float la = a.pixels[4 * i] + a.pixels[4 * i + 1] + a.pixels[4 * i + 2];
    const float lb = b.pixels[4 * i] + b.pixels[4 * i + 1] + b.pixels[4 * i + 2];
    e.darker += lb < darkerBelow * la ? 1u : 0u;
    e.brighter += lb > 1.01f * la ? 1u : 0u;
  }
  return e;
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

TEST(HeadlessCapture, FliesOverAUserSuppliedTerrain) {
  const fs::path dir = freshDir("user_terrain");
  ASSERT_EQ(runSample("--headless --frames 1 --width 96 --height 54 --validation --terrain " +
                      std::string(HILLS_TERRAIN) + " --scene " + scene("terrain_only.json") +
                      " --capture " + dir.string()),
            0);
  EXPECT_TRUE(fs::exists(dir / "frame_0000.png"));
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

}  // namespace
