// stb_image compiled privately (static functions, PNG and JPEG only) so that no other format's
// decoder is reachable from a glTF file and the copy inside libtinygltf is never called.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_NO_HDR
#define STBI_NO_LINEAR
#include <stb/stb_image.h>

#include "gltf_image_decode.h"

#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include "engine/core/error.h"
#include "gltf_checked_math.h"

namespace engine::assets::gltf {

ImageRgba8 decodePngOrJpeg(std::span<const std::uint8_t> bytes, std::uint64_t maxDecodedBytes) {
  if (bytes.empty()) throw Error("image data is empty");
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw Error("image data is over 2 GiB");
  }
  const auto length = static_cast<int>(bytes.size());
  int width = 0;
  int height = 0;
  int channels = 0;
  if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels)) {
    throw Error(std::string("cannot decode image (not a valid PNG or JPEG): ") +
                stbi_failure_reason());
  }
  const std::uint64_t decodedBytes = checkedMul(
      checkedMul(static_cast<std::uint64_t>(width), static_cast<std::uint64_t>(height)), 4);
  if (width <= 0 || height <= 0 || decodedBytes > maxDecodedBytes) {
    throw Error("image is " + std::to_string(width) + "x" + std::to_string(height) +
                ", over the decoded size limit of " + std::to_string(maxDecodedBytes) + " bytes");
  }

  int decodedWidth = 0;
  int decodedHeight = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(bytes.data(), length, &decodedWidth, &decodedHeight, &channels, 4),
      &stbi_image_free);
  if (!pixels) {
    throw Error(std::string("cannot decode image: ") + stbi_failure_reason());
  }
  if (decodedWidth != width || decodedHeight != height) {
    throw Error("image size changed between header and decode");
  }
  ImageRgba8 image;
  image.width = static_cast<std::uint32_t>(width);
  image.height = static_cast<std::uint32_t>(height);
  image.pixels.resize(static_cast<std::size_t>(decodedBytes));
  std::memcpy(image.pixels.data(), pixels.get(), image.pixels.size());
  return image;
}

}  // namespace engine::assets::gltf
