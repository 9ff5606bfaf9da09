// The sample's water sorts with the clouds, both ways, as the clouds module's README asks of a
// host's transparent surface: drawn in the scene pass, writing its depth, before the clouds march
// (sample_game/shaders/water_fragment.glsl). Seen from 1 km over a lake 400 m deep: a small cloud
// above the water composites over it, and one under its surface, which nothing physical could
// put there but which a water that wrote no depth would show, stays hidden. The scene
// (tests/sample_game/scenes/water_sorting.json) holds both clouds; the tests render it with one,
// both or neither, with and without the water, and compare the frames (HDR, manual exposure;
// no cloud shadows or sky light, so the water's own colour owes nothing to the clouds).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/assets/image_io.h"
#include "engine/core/json_reader.h"
#include "sample_runs.h"

namespace {

namespace fs = std::filesystem;
using engine::assets::ImageRgba32f;
using namespace sample_tests;

// The two hero clouds of water_sorting.json, by their place in its list.
constexpr std::size_t kCloudOverTheWater = 0;
constexpr std::size_t kCloudUnderTheSurface = 1;

struct Variant {
  const char* name;
  bool water = true;
  bool over = true;                // the cloud over the water
  bool under = true;               // the cloud under its surface
  double underBaseMetres = 300.0;  // where that cloud's base is (the water is at 600 m)
};

// The last of 8 frames of the scene as `variant` changes it, 160 x 90, HDR.
ImageRgba32f render(const Variant& variant) {
  nlohmann::json json = engine::JsonReader::parseFile(scene("water_sorting.json"));
  if (!variant.water) json.erase("water");
  nlohmann::json& clouds = json["clouds"]["heroClouds"];
  clouds[kCloudUnderTheSurface]["positionMetres"][1] = variant.underBaseMetres;
  nlohmann::json kept = nlohmann::json::array();
  if (variant.over) kept.push_back(clouds[kCloudOverTheWater]);
  if (variant.under) kept.push_back(clouds[kCloudUnderTheSurface]);
  if (kept.empty())
    json["clouds"].erase("heroClouds");
  else
    clouds = kept;
  const fs::path dir = freshDir(variant.name);
  fs::create_directories(dir);
  return renderLastFrame(dir, json.dump(2), 8, 160, 90);
}

float luminance(const float* p) {
  return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

// The share of pixels whose luminance differs between the frames by more than `relative` of the
// larger, and the largest relative difference.
struct Difference {
  double share = 0.0;
  double largest = 0.0;
};
Difference difference(const ImageRgba32f& a, const ImageRgba32f& b, double relative) {
  Difference d;
  const std::size_t pixels = std::size_t(a.width) * a.height;
  if (b.pixels.size() != a.pixels.size() || pixels == 0) return {1.0, 1e9};
  std::size_t differing = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    const double la = luminance(&a.pixels[4 * i]);
    const double lb = luminance(&b.pixels[4 * i]);
    const double r = std::abs(la - lb) / std::max({la, lb, 1e-6});
    d.largest = std::max(d.largest, r);
    if (r > relative) ++differing;
  }
  d.share = double(differing) / double(pixels);
  return d;
}

// A cloud under the water's surface: the water hides it (the frame is that of the lake without
// it), though it would show without the water and does show once raised above the surface.
TEST(WaterCapture, ACloudUnderTheSurfaceDoesNotShowThroughIt) {
  const ImageRgba32f both = render({"under_both"});
  const ImageRgba32f overOnly = render({"under_over_only", true, true, false});
  const Difference hidden = difference(both, overOnly, 0.002);
  std::printf("under the surface: %.2f%% of pixels differ by 0.2%%, largest %.4f\n",
              100.0 * hidden.share, hidden.largest);
  EXPECT_EQ(hidden.share, 0.0) << "the cloud under the water shows through it";

  // Negative controls: the same cloud is in view, seen without the water (over the lake's bed)
  // and raised 20 m above the surface.
  const Difference dry = difference(render({"under_dry", false, true, true}),
                                    render({"under_dry_over_only", false, true, false}), 0.05);
  const Difference raised =
      difference(render({"under_raised", true, true, true, 620.0}), overOnly, 0.05);
  std::printf("without the water %.2f%%, raised above it %.2f%% of pixels 5%% different\n",
              100.0 * dry.share, 100.0 * raised.share);
  EXPECT_GT(dry.share, 0.005) << "without the water, the cloud over the bed is in view";
  EXPECT_GT(raised.share, 0.005) << "over the surface, the cloud is in view";
}

// A cloud in front of the water: the frame is the water behind the cloud's transmittance plus its
// light, the same as the cloud over the bare bed. So per pixel, with the cloud (1) and without
// (0), water (W) and bed (B): W1 - B1 = T (W0 - B0), one T in [0, 1] for all three channels, and
// well under 1 where the cloud covers the water. A water drawn over the composited clouds would
// give T = 1 everywhere (it would hide the cloud).
TEST(WaterCapture, ACloudInFrontOfTheWaterCompositesOverIt) {
  const ImageRgba32f w1 = render({"front_water_cloud", true, true, false});
  const ImageRgba32f b1 = render({"front_bed_cloud", false, true, false});
  const ImageRgba32f w0 = render({"front_water", true, false, false});
  const ImageRgba32f b0 = render({"front_bed", false, false, false});
  ASSERT_EQ(w1.pixels.size(), b0.pixels.size());
  std::size_t waterPixels = 0, covered = 0, outOfRange = 0, inconsistent = 0;
  double worstSpread = 0.0;
  for (std::size_t i = 0; i < std::size_t(w1.width) * w1.height; ++i) {
    float lo = 1e9f, hi = -1e9f;
    int channels = 0;
    for (std::size_t c = 4 * i; c < 4 * i + 3; ++c) {
      const float seen = w0.pixels[c] - b0.pixels[c];
      // Channels where the water differs from the bed by over 5% of the pixel's light.
      if (std::abs(seen) < 0.05f * std::max(w0.pixels[c], b0.pixels[c])) continue;
      const float t = (w1.pixels[c] - b1.pixels[c]) / seen;
      lo = std::min(lo, t);
      hi = std::max(hi, t);
      ++channels;
    }
    if (channels == 0) continue;
    ++waterPixels;
    if (lo < -0.02f || hi > 1.02f) ++outOfRange;
    if (hi < 0.5f) ++covered;
    if (channels > 1) {
      worstSpread = std::max(worstSpread, double(hi - lo));
      if (hi - lo > 0.05f) ++inconsistent;
    }
  }
  std::printf(
      "in front: %zu water pixels, %zu covered (T < 0.5), %zu out of [0, 1], "
      "%zu with channels 0.05 apart (worst %.4f)\n",
      waterPixels, covered, outOfRange, inconsistent, worstSpread);
  ASSERT_GT(waterPixels, std::size_t(w1.width) * w1.height / 2) << "the lake fills the view";
  EXPECT_GT(covered, waterPixels / 100) << "the cloud covers the water in front of it";
  EXPECT_EQ(outOfRange, 0u);
  EXPECT_LE(inconsistent, waterPixels / 200);
}

// A storm's flash lights the water as it lights the terrain (water_fragment.glsl's lightning
// variant): the scripted strike of the storm scene (HeadlessCapture.AScriptedStrikeGlowsAndLeaves
// NoGhost) over a lake at 450 m, 50 m under the camera, which fills the lower third of the view.
// While the flash lasts, nearly all of the water is brighter than in the same frame without it:
// the deck its ripples reflect glows with the flash's sky light, and its body takes that and the
// core's direct light.
TEST(WaterCapture, AStormsFlashLightsTheWater) {
  const auto run = [](const char* name, bool water, const char* script) {
    nlohmann::json json = engine::JsonReader::parseFile(scene("storm_calm.json"));
    if (water) json["water"] = {{"levelMetres", 450.0}};
    const fs::path dir = freshDir(name);
    fs::create_directories(dir);
    const fs::path file = dir / "scene.json";
    std::ofstream(file) << json.dump(2);
    const std::string arguments =
        "--headless --validation --fixed-dt 0.0333 --width 160 --height 90 --no-hud --scene " +
        file.string() + " --capture " + (dir / "out").string() + " --script " +
        std::string(SAMPLE_TEST_DIR) + "/scripts/" + script;
    EXPECT_EQ(runSample(arguments), 0) << arguments;
    return engine::assets::readImage(dir / "out" / "during.exr");
  };
  const ImageRgba32f calm = run("lake_storm_calm", true, "no_strike.json");
  const ImageRgba32f struck = run("lake_storm_struck", true, "scripted_strike.json");
  const ImageRgba32f dry = run("lake_storm_dry", false, "no_strike.json");
  ASSERT_EQ(calm.pixels.size(), struck.pixels.size());
  ASSERT_EQ(calm.pixels.size(), dry.pixels.size());
  const std::size_t pixels = std::size_t(calm.width) * calm.height;
  std::size_t water = 0;
  std::size_t lit = 0;
  for (std::size_t i = pixels * 2 / 3; i < pixels; ++i) {
    const float before = luminance(&calm.pixels[4 * i]);
    // Water: the lake changes the pixel against the same frame over its bed.
    if (std::abs(before - luminance(&dry.pixels[4 * i])) < 0.02f * before) continue;
    ++water;
    if (luminance(&struck.pixels[4 * i]) > 1.02f * before) ++lit;
  }
  const std::size_t lowerThird = pixels - pixels * 2 / 3;
  std::printf(
      "a flash over the lake: %zu of %zu water pixels 2%% brighter (%zu in the lower third)\n", lit,
      water, lowerThird);
  ASSERT_GT(water, lowerThird / 2) << "the lake fills most of the lower third";
  EXPECT_GT(lit, water * 9 / 10) << "the flash lights the water";
}

}  // namespace
