#pragma once
// PNG and JPEG decoding from memory, sized before it allocates.
#include <cstdint>
#include <span>

#include "engine/assets/image_io.h"

namespace engine::assets::gltf {

// Decodes PNG or JPEG bytes (the two formats core glTF allows) to RGBA8. Reads the header
// first and refuses an image whose 4 * width * height exceeds `maxDecodedBytes` before any
// pixel memory is allocated. Throws engine::Error describing the fault.
ImageRgba8 decodePngOrJpeg(std::span<const std::uint8_t> bytes, std::uint64_t maxDecodedBytes);

}  // namespace engine::assets::gltf
