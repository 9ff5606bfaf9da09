#include "gltf_texture.h"

#include <span>
#include <string>

#include "engine/core/error.h"
#include "gltf_checked_math.h"
#include "gltf_image_decode.h"

namespace engine::assets::gltf {
namespace {

std::span<const std::uint8_t> imageBytes(const tinygltf::Model& model, std::size_t imageIndex) {
  const tinygltf::Image& image = model.images[imageIndex];
  const std::string what = "image " + std::to_string(imageIndex);
  if (image.bufferView < 0) {
    // URI image: the parse step kept the file's bytes (or tinygltf could not read the file).
    if (!image.as_is || image.image.empty()) throw Error(what + ": image data could not be read");
    return image.image;
  }
  const auto viewIndex = static_cast<std::size_t>(image.bufferView);
  if (viewIndex >= model.bufferViews.size()) {
    throw Error(what + ": bufferView " + std::to_string(viewIndex) + " is out of range (" +
                std::to_string(model.bufferViews.size()) + " bufferViews)");
  }
  const tinygltf::BufferView& view = model.bufferViews[viewIndex];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    throw Error(what + ": bufferView " + std::to_string(viewIndex) + ": buffer " +
                std::to_string(view.buffer) + " is out of range");
  }
  const tinygltf::Buffer& buffer = model.buffers[static_cast<std::size_t>(view.buffer)];
  if (!rangeFits(view.byteOffset, view.byteLength, buffer.data.size())) {
    throw Error(what + ": bufferView " + std::to_string(viewIndex) + " (byteOffset " +
                std::to_string(view.byteOffset) + ", byteLength " +
                std::to_string(view.byteLength) + ") lies outside buffer " +
                std::to_string(view.buffer) + " (" + std::to_string(buffer.data.size()) +
                " bytes)");
  }
  return std::span<const std::uint8_t>(buffer.data).subspan(view.byteOffset, view.byteLength);
}

}  // namespace

void validateImageRanges(const tinygltf::Model& model) {
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    if (model.images[i].bufferView >= 0) (void)imageBytes(model, i);
  }
}

ImageRgba8 loadBaseColorTexture(const tinygltf::Model& model, std::uint64_t maxDecodedBytes) {
  if (model.materials.empty()) return {};
  const int textureIndex = model.materials[0].pbrMetallicRoughness.baseColorTexture.index;
  if (textureIndex == -1) return {};
  if (textureIndex < 0 || static_cast<std::size_t>(textureIndex) >= model.textures.size()) {
    throw Error("material 0: baseColorTexture " + std::to_string(textureIndex) +
                " is out of range (" + std::to_string(model.textures.size()) + " textures)");
  }
  const int source = model.textures[static_cast<std::size_t>(textureIndex)].source;
  if (source == -1) return {};
  if (source < 0 || static_cast<std::size_t>(source) >= model.images.size()) {
    throw Error("texture " + std::to_string(textureIndex) + ": source image " +
                std::to_string(source) + " is out of range (" +
                std::to_string(model.images.size()) + " images)");
  }
  const auto imageIndex = static_cast<std::size_t>(source);
  const std::span<const std::uint8_t> bytes = imageBytes(model, imageIndex);
  try {
    return decodePngOrJpeg(bytes, maxDecodedBytes);
  } catch (const Error& e) {
    throw Error("image " + std::to_string(imageIndex) + ": " + e.what());
  }
}

}  // namespace engine::assets::gltf
