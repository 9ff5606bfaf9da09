#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <vector>

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

// A PNG of a signature, an IHDR claiming `width` x `height` RGBA8 pixels, an IDAT without
// pixels and IEND: the header is all a reader sees before it sizes its buffers.
std::vector<std::uint8_t> pngHeaderOnly(std::uint32_t width, std::uint32_t height) {
  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const auto chunk = [&png](const char* type, const std::vector<std::uint8_t>& data) {
    const auto appendBe = [&png](std::uint32_t v) {
      for (int shift = 24; shift >= 0; shift -= 8) png.push_back(std::uint8_t(v >> shift));
    };
    appendBe(static_cast<std::uint32_t>(data.size()));
    const std::size_t start = png.size();
    png.insert(png.end(), type, type + 4);
    png.insert(png.end(), data.begin(), data.end());
    std::uint32_t crc = 0xFFFFFFFFu;  // CRC-32 of type and data, as PNG defines it
    for (std::size_t i = start; i < png.size(); ++i) {
      crc ^= png[i];
      for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    appendBe(~crc);
  };
  std::vector<std::uint8_t> ihdr;
  for (std::uint32_t v : {width, height}) {
    for (int shift = 24; shift >= 0; shift -= 8) ihdr.push_back(std::uint8_t(v >> shift));
  }
  ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, no filter, no interlace
  chunk("IHDR", ihdr);
  chunk("IDAT", {0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});  // an empty zlib stream
  chunk("IEND", {});
  return png;
}

TEST(ImageIo, AnImageLargerThanTheLimitIsRejectedBeforeItsPixelsAreRead) {
  std::filesystem::create_directories(scratch(""));
  const auto write = [](const char* name, const std::vector<std::uint8_t>& bytes) {
    std::FILE* f = std::fopen(scratch(name).c_str(), "wb");
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
  };
  write("huge.png", pngHeaderOnly(65536, 65536));
  try {
    readImage(scratch("huge.png"));
    FAIL() << "a 65536 x 65536 header must be rejected";
  } catch (const engine::Error& e) {
    EXPECT_NE(std::string(e.what()).find("huge.png: 65536 x 65536 pixels is more than"),
              std::string::npos)
        << e.what();
  }
  // At the limit the header passes the size check and the missing pixels are what fail.
  write("at_limit.png", pngHeaderOnly(8192, 8192));
  try {
    readImage(scratch("at_limit.png"));
    FAIL() << "a PNG without pixel data must not read";
  } catch (const engine::Error& e) {
    EXPECT_EQ(std::string(e.what()).find("is more than"), std::string::npos) << e.what();
  }
}

}  // namespace
