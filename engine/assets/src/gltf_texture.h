#pragma once
// The base colour texture of the first material, located and range-checked before decoding.
#include <cstdint>

#include <tiny_gltf.h>

#include "engine/assets/image_io.h"

namespace engine::assets::gltf {

// Checks that every image given by bufferView lies inside its buffer's actual data, whether or
// not a material uses it. Throws engine::Error naming the image and bufferView.
void validateImageRanges(const tinygltf::Model& model);

// Follows materials[0].pbrMetallicRoughness.baseColorTexture to its texture and image, checks
// every index and, for a bufferView image, that the view lies inside its buffer's actual data,
// then decodes it (decoded size capped at `maxDecodedBytes`). Returns an empty image when there
// is no material, no base colour texture, or a texture without a core source (an extension's).
// Throws engine::Error naming the material/texture/image index.
ImageRgba8 loadBaseColorTexture(const tinygltf::Model& model, std::uint64_t maxDecodedBytes);

}  // namespace engine::assets::gltf
