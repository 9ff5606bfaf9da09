// Runs the module's minimal raw-Vulkan host as a user would, with validation on, and checks
// that its image has clouds: compared with the same scene rendered without the module, a
// good share of the sky changed, the ground-occluded boxes did not turn into cloud, and the
// picture is neither empty nor saturated.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "engine/assets/image_io.h"

namespace {

namespace fs = std::filesystem;

int run(const std::string& arguments) {
  const std::string command = std::string(MINIMAL_HOST_EXE) + " --validation " + arguments;
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(MinimalHost, RendersCloudsValidationClean) {
  const fs::path dir = fs::temp_directory_path() / "cloudscape_minimal_host";
  fs::create_directories(dir);
  ASSERT_EQ(run("--width 192 --height 108 --output " + (dir / "clouds.png").string()), 0);
  ASSERT_EQ(run("--width 192 --height 108 --no-clouds --output " + (dir / "plain.png").string()), 0);
  const auto clouds = engine::assets::readImage(dir / "clouds.png");
  const auto plain = engine::assets::readImage(dir / "plain.png");
  ASSERT_EQ(clouds.width, 192u);
  ASSERT_EQ(clouds.height, 108u);

  std::size_t changed = 0;
  std::size_t saturated = 0;
  std::size_t pixels = std::size_t{clouds.width} * clouds.height;
  for (std::size_t i = 0; i < pixels; ++i) {
    const float* a = &clouds.pixels[4 * i];
    const float* b = &plain.pixels[4 * i];
    const float d = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
    changed += d > 0.03f ? 1 : 0;
    saturated += (a[0] > 0.995f && a[1] > 0.995f && a[2] > 0.995f) ? 1 : 0;
  }
  EXPECT_GT(changed, pixels / 10) << "clouds changed too little of the picture";
  EXPECT_LT(changed, pixels) << "everything changed";
  EXPECT_LT(saturated, pixels / 20) << "the picture is blown out";
  // The bottom rows see only the ground in front of the camera: no cloud can be there.
  for (std::uint32_t x = 0; x < clouds.width; ++x) {
    const float* a = clouds.at(x, clouds.height - 2);
    const float* b = plain.at(x, clouds.height - 2);
    ASSERT_NEAR(a[0], b[0], 1.5f / 255.0f) << "cloud drawn over near ground at x " << x;
  }
}

}  // namespace
