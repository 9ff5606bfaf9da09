// The terrain's close-up detail as a scene turns it off (`terrain.closeDetail`: its code compiled
// out of the terrain's fragments), rendered headless without clouds: low over the foothills the
// ground loses its detail, and from high up, where every pixel covers more than 15 m of ground
// and the detail has faded out, the frame is the same to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "engine/assets/image_io.h"
#include "sample_runs.h"

namespace {

namespace fs = std::filesystem;
using engine::assets::ImageRgba32f;
using namespace sample_tests;

// The generated terrain from `cameraJson`, with or without its close-up detail, 160x90, HDR.
ImageRgba32f render(const char* name, const char* cameraJson, bool closeDetail) {
  const fs::path dir = freshDir(name);
  fs::create_directories(dir);
  const std::string sceneJson = std::string(R"({"name": "the ground up close", "camera": )") +
                                cameraJson + R"(, "sun": {"timeOfDayHours": 15.5},
    "terrain": {"gltf": "default", "closeDetail": )" +
                                (closeDetail ? "true" : "false") + R"(},
    "exposure": {"mode": "manual", "ev100": 14}})";
  return renderLastFrame(dir, sceneJson, 2, 160, 90);
}

// The share of pixels whose luminance differs by more than 2% of the larger.
double differingShare(const ImageRgba32f& a, const ImageRgba32f& b) {
  const std::size_t pixels = std::size_t(a.width) * a.height;
  if (pixels == 0 || a.pixels.size() != b.pixels.size()) return 1.0;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    const auto luminance = [&](const ImageRgba32f& image) {
      const float* p = &image.pixels[4 * i];
      return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    };
    const double la = luminance(a);
    const double lb = luminance(b);
    if (std::abs(la - lb) > 0.02 * std::max({la, lb, 1e-6})) ++differing;
  }
  return double(differing) / double(pixels);
}

// The default scene's camera: 320 m up, looking at a hillside a few hundred metres away.
constexpr const char* kLowCamera =
    R"({"position": [0, 320, 17000], "yawDegrees": -45, "pitchDegrees": 7,
        "speedMetresPerSecond": 0})";
// 9 km up, looking down at the range: a pixel covers 50 m or more of the ground.
constexpr const char* kHighCamera =
    R"({"position": [0, 9000, 17000], "yawDegrees": -45, "pitchDegrees": -60,
        "speedMetresPerSecond": 0})";

TEST(TerrainCloseDetail, OffTheGroundUpCloseLosesItsDetail) {
  const ImageRgba32f detailed = render("detail_low_on", kLowCamera, true);
  const ImageRgba32f plain = render("detail_low_off", kLowCamera, false);
  const double share = differingShare(detailed, plain);
  std::printf("close-up detail, low: %.1f%% of the pixels 2%% different\n", 100.0 * share);
  EXPECT_GT(share, 0.1) << "the hillside's colour and relief at the scales a pixel resolves";
}

TEST(TerrainCloseDetail, FromHighUpTheFrameIsTheSameWithoutIt) {
  const ImageRgba32f detailed = render("detail_high_on", kHighCamera, true);
  const ImageRgba32f plain = render("detail_high_off", kHighCamera, false);
  ASSERT_FALSE(detailed.pixels.empty());
  EXPECT_EQ(detailed.pixels, plain.pixels) << "no pixel resolves what the detail adds";
}

}  // namespace
