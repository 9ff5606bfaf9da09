#include <gtest/gtest.h>

#include <filesystem>

#include "engine/assets/image_io.h"
#include "engine/core/error.h"

namespace {

using namespace engine::assets;

std::filesystem::path scratch(const char* name) {
  return std::filesystem::temp_directory_path() / "cloudscape_image_io_test" / name;
}

TEST(ImageIo, PngRoundTripsExactly) {
  ImageRgba8 image{5, 3, {}};
  for (std::uint32_t i = 0; i < 5 * 3 * 4; ++i)
    image.pixels.push_back(static_cast<std::uint8_t>(i * 7));
  writePng(scratch("a.png"), image);
  const ImageRgba32f read = readImage(scratch("a.png"));
  ASSERT_EQ(read.width, 5u);
  ASSERT_EQ(read.height, 3u);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    EXPECT_NEAR(read.pixels[i] * 255.0f, image.pixels[i], 1e-3f) << i;
  }
}

TEST(ImageIo, ExrKeepsHdrValuesToHalfPrecision) {
  ImageRgba32f image{4, 2, {}};
  for (std::uint32_t i = 0; i < 4 * 2 * 4; ++i)
    image.pixels.push_back(0.01f + 37.5f * static_cast<float>(i));
  writeExr(scratch("a.exr"), image);
  const ImageRgba32f read = readImage(scratch("a.exr"));
  ASSERT_EQ(read.width, 4u);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    EXPECT_NEAR(read.pixels[i], image.pixels[i], image.pixels[i] * 1e-3f) << i;
  }
}

TEST(ImageIo, ErrorsNameTheFile) {
  try {
    readImage(scratch("missing.png"));
    FAIL();
  } catch (const engine::Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
  }
  std::filesystem::create_directories(scratch(""));
  {
    std::FILE* f = std::fopen(scratch("garbage.png").c_str(), "wb");
    std::fputs("not a png", f);
    std::fclose(f);
  }
  EXPECT_THROW(readImage(scratch("garbage.png")), engine::Error);
  EXPECT_THROW(writePng(scratch("bad.png"), ImageRgba8{2, 2, {1, 2, 3}}), engine::Error);
}

}  // namespace
