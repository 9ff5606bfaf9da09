#pragma once
// Image files through OpenImageIO: PNG for LDR (8-bit sRGB-encoded, already tonemapped) and
// OpenEXR for HDR (half-float, linear). Reading converts any supported file to float RGBA.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace engine::assets {

// Interleaved RGBA, row 0 at the top.
struct ImageRgba8 {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> pixels;  // 4 * width * height
};

struct ImageRgba32f {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> pixels;  // 4 * width * height, linear
  float* at(std::uint32_t x, std::uint32_t y) { return &pixels[4 * (std::size_t{y} * width + x)]; }
  const float* at(std::uint32_t x, std::uint32_t y) const {
    return &pixels[4 * (std::size_t{y} * width + x)];
  }
};

// Writers create parent folders and throw engine::Error naming the file on failure.
void writePng(const std::filesystem::path& path, const ImageRgba8& image);
void writeExr(const std::filesystem::path& path, const ImageRgba32f& image);

// The most pixels readImage() accepts (8192 x 8192): its float read buffer is then at most 1 GiB
// for four channels.
inline constexpr std::uint64_t kMaxImagePixels = 8192ull * 8192ull;

// Reads PNG, EXR or any format OpenImageIO knows into float RGBA (8-bit values map to [0, 1]
// without sRGB decoding; missing channels: grey to RGB, alpha 1). Throws engine::Error naming
// the file when it is missing, cannot be decoded or is larger than kMaxImagePixels.
ImageRgba32f readImage(const std::filesystem::path& path);

}  // namespace engine::assets
