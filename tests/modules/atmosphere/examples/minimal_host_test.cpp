// Runs the atmosphere module's minimal raw-Vulkan host as a user would, with validation on, and
// checks its picture: a blue sky overhead, and a ground hazed by the module (its flat grey,
// uploaded the same in every pixel, changes with distance: the far ground fades towards the
// sky at the horizon, the near ground much less). Then as a host
// that enables only what the module's README requires (no extension at all), under the
// validation layer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "engine/assets/image_io.h"
#include "example_host.h"

namespace {

namespace fs = std::filesystem;

struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;
};

// The mean colour of row `y`.
Rgb rowMean(const engine::assets::ImageRgba32f& image, std::uint32_t y) {
  Rgb mean;
  for (std::uint32_t x = 0; x < image.width; ++x) {
    mean.r += image.at(x, y)[0] / float(image.width);
    mean.g += image.at(x, y)[1] / float(image.width);
    mean.b += image.at(x, y)[2] / float(image.width);
  }
  return mean;
}

TEST(AtmosphereMinimalHost, RendersSkyAndHazeValidationClean) {
  const fs::path picture = fs::temp_directory_path() / "cloudscape_atmosphere_host.ppm";
  ASSERT_EQ(test::runExampleHost(MINIMAL_HOST_EXE,
                                 "--width 160 --height 90 --frames 2 --output " + picture.string()),
            0);
  const auto image = engine::assets::readImage(picture);
  ASSERT_EQ(image.width, 160u);
  ASSERT_EQ(image.height, 90u);
  const Rgb top = rowMean(image, 0);
  EXPECT_GT(top.b, top.r) << "a clear sky overhead is blue";
  EXPECT_GT(top.b, 0.05f) << "and not black";
  // The camera, 300 m up, looks 0.05 rad above the horizon with a vertical field of view of
  // 1.1 rad: the horizon lies at row 48.7 of 90. The bottom row sees the ground about 630 m
  // away, row 50 about 12 km away, row 47 the sky just above the horizon.
  const Rgb near = rowMean(image, image.height - 1);
  const Rgb far = rowMean(image, 50);
  const Rgb horizon = rowMean(image, 47);
  const auto distance = [](const Rgb& a, const Rgb& b) {
    return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
  };
  // Every ground pixel was uploaded the same: any difference is the module's haze.
  EXPECT_GT(distance(near, far), 0.05f) << "the far ground must be hazed differently";
  EXPECT_LT(distance(far, horizon), distance(near, horizon))
      << "the far ground fades towards the sky at the horizon";
}

TEST(AtmosphereMinimalHost, AHostThatEnablesNothingOptionalIsValidationClean) {
  const std::string picture =
      (fs::temp_directory_path() / "cloudscape_atmosphere_strict.ppm").string();
  std::string log;
  ASSERT_EQ(test::runExampleHostUnderLayer(
                MINIMAL_HOST_EXE, "--width 96 --height 54 --frames 4 --output " + picture, log),
            0)
      << log;
  EXPECT_GT(test::occurrences(log, "wrote"), 0u) << log;
  EXPECT_EQ(test::occurrences(log, "Validation Error"), 0u) << log;
  EXPECT_EQ(test::occurrences(log, "VUID"), 0u) << log;
}

}  // namespace
