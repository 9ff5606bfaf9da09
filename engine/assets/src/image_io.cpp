// The only translation unit that includes OpenImageIO (its headers cost seconds per file).
#include "engine/assets/image_io.h"

#include <OpenImageIO/imageio.h>

#include <string>

#include "engine/core/error.h"

namespace engine::assets {
namespace {

void ensureParent(const std::filesystem::path& path) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
}

void writeImage(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                OIIO::TypeDesc fileType, OIIO::TypeDesc memoryType, const void* pixels,
                std::size_t expectedValues, std::size_t actualValues) {
  const std::string name = path.string();
  if (width == 0 || height == 0 || expectedValues != actualValues) {
    throw Error(name + ": image has " + std::to_string(actualValues) + " values, expected " +
                std::to_string(expectedValues) + " for " + std::to_string(width) + "x" +
                std::to_string(height) + " RGBA");
  }
  ensureParent(path);
  auto out = OIIO::ImageOutput::create(name);
  if (!out) throw Error(name + ": cannot create image writer: " + OIIO::geterror());
  OIIO::ImageSpec spec(static_cast<int>(width), static_cast<int>(height), 4, fileType);
  // Our pixels are straight (unassociated) alpha; without this OIIO would un-premultiply them.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(name, spec)) throw Error(name + ": cannot open for writing: " + out->geterror());
  if (!out->write_image(memoryType, pixels)) {
    throw Error(name + ": write failed: " + out->geterror());
  }
  if (!out->close()) throw Error(name + ": close failed: " + out->geterror());
}

}  // namespace

void writePng(const std::filesystem::path& path, const ImageRgba8& image) {
  writeImage(path, image.width, image.height, OIIO::TypeDesc::UINT8, OIIO::TypeDesc::UINT8,
             image.pixels.data(), std::size_t{4} * image.width * image.height, image.pixels.size());
}

void writeExr(const std::filesystem::path& path, const ImageRgba32f& image) {
  writeImage(path, image.width, image.height, OIIO::TypeDesc::HALF, OIIO::TypeDesc::FLOAT,
             image.pixels.data(), std::size_t{4} * image.width * image.height, image.pixels.size());
}

ImageRgba32f readImage(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::is_regular_file(path)) throw Error(name + ": image file not found");
  // Keep straight alpha as stored; by default OIIO premultiplies PNG colours on read.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(name, &config);
  if (!in) throw Error(name + ": cannot decode image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const int channels = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0 || channels <= 0 || channels > 64) {
    throw Error(name + ": unsupported image size or channel count");
  }
  // The header alone decides what is allocated: a 100-byte file may claim 65536 x 65536 pixels
  // (a 64 GiB read buffer). The project's largest image is a few megapixels.
  const auto pixels = std::uint64_t(spec.width) * std::uint64_t(spec.height);
  if (pixels > kMaxImagePixels) {
    throw Error(name + ": " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                " pixels is more than the " + std::to_string(kMaxImagePixels) +
                " an image may have");
  }
  std::vector<float> raw(static_cast<std::size_t>(spec.width) *
                         static_cast<std::size_t>(spec.height) *
                         static_cast<std::size_t>(channels));
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data())) {
    throw Error(name + ": read failed: " + in->geterror());
  }
  in->close();

  ImageRgba32f image;
  image.width = static_cast<std::uint32_t>(spec.width);
  image.height = static_cast<std::uint32_t>(spec.height);
  image.pixels.resize(std::size_t{4} * image.width * image.height);
  const auto c = static_cast<std::size_t>(channels);
  for (std::size_t i = 0; i < std::size_t{image.width} * image.height; ++i) {
    const float* src = &raw[i * c];
    float* dst = &image.pixels[i * 4];
    dst[0] = src[0];
    dst[1] = c >= 3 ? src[1] : src[0];
    dst[2] = c >= 3 ? src[2] : src[0];
    dst[3] = c == 4 ? src[3] : (c == 2 ? src[1] : 1.0f);
  }
  return image;
}

}  // namespace engine::assets
