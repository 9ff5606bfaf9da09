// Runs the sample binary headless, as a user would, and checks what it wrote: the exit code
// (non-zero on any validation message), the image sizes and the content (sky above, ground
// below, the test pattern in the middle, HDR values above 1 in the EXR, nothing non-finite).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
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

fs::path freshDir(const char* name) {
  const fs::path dir = fs::temp_directory_path() / "cloudscape_sample_tests" / name;
  fs::remove_all(dir);
  return dir;
}

TEST(HeadlessCapture, WritesPngAndExrOfTheLastFrame) {
  const fs::path dir = freshDir("last");
  ASSERT_EQ(runSample("--headless --frames 3 --width 160 --height 90 --validation --capture " +
                      dir.string()),
            0);
  ASSERT_FALSE(fs::exists(dir / "frame_0000.png")) << "only the last frame by default";
  const ImageRgba32f png = engine::assets::readImage(dir / "frame_0002.png");
  const ImageRgba32f exr = engine::assets::readImage(dir / "frame_0002.exr");
  ASSERT_EQ(png.width, 160u);
  ASSERT_EQ(png.height, 90u);
  ASSERT_EQ(exr.width, 160u);
  ASSERT_EQ(exr.height, 90u);

  // Sky at the top: blue dominates. Ground at the bottom corners: darker than the sky.
  const float* top = png.at(5, 2);
  EXPECT_GT(top[2], top[0]) << "top-left should be sky blue";
  const float* bottom = png.at(5, 88);
  EXPECT_LT(bottom[0] + bottom[1] + bottom[2], top[0] + top[1] + top[2]);

  // The test pattern: somewhere in the middle band a strongly red, a green and a blue quad.
  bool red = false, green = false, blue = false;
  for (std::uint32_t y = 45; y < 90; ++y) {
    for (std::uint32_t x = 40; x < 120; ++x) {
      const float* p = exr.at(x, y);
      red = red || (p[0] > 1.5f && p[0] > 3 * p[1]);
      green = green || (p[1] > 1.5f && p[1] > 3 * p[0]);
      blue = blue || (p[2] > 1.5f && p[2] > 3 * p[0]);
    }
  }
  EXPECT_TRUE(red && green && blue) << "red " << red << " green " << green << " blue " << blue;

  for (float v : exr.pixels) ASSERT_TRUE(std::isfinite(v));
}

TEST(HeadlessCapture, CaptureAllWritesEveryFrameAndRunsAreDeterministic) {
  const fs::path a = freshDir("all_a");
  const fs::path b = freshDir("all_b");
  const std::string common = "--headless --frames 2 --fixed-dt 0.5 --width 96 --height 64 --capture-all --capture ";
  ASSERT_EQ(runSample(common + a.string()), 0);
  ASSERT_EQ(runSample(common + b.string()), 0);
  for (const char* name : {"frame_0000.png", "frame_0001.png"}) {
    const ImageRgba32f x = engine::assets::readImage(a / name);
    const ImageRgba32f y = engine::assets::readImage(b / name);
    ASSERT_EQ(x.pixels, y.pixels) << name << " differs between identical runs";
  }
  // The pattern spins with time: consecutive frames differ.
  EXPECT_NE(engine::assets::readImage(a / "frame_0000.png").pixels,
            engine::assets::readImage(a / "frame_0001.png").pixels);
}

TEST(HeadlessCapture, BadArgumentsFailWithAMessage) {
  EXPECT_NE(runSample("--headless --width 0 2>/dev/null"), 0);
  EXPECT_NE(runSample("--headless --frames banana 2>/dev/null"), 0);
  EXPECT_NE(runSample("--no-such-option 2>/dev/null"), 0);
}

}  // namespace
