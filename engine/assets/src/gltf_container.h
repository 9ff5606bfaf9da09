#pragma once
// The binary glTF (.glb) container: header and chunk table, checked before tinygltf sees the
// bytes (2.7.0 lets a BIN chunk run 8 bytes past the end of the file).
#include <cstddef>
#include <cstdint>
#include <span>

namespace engine::assets::gltf {

// Byte ranges of a .glb's chunks inside the file; every range lies inside the file.
struct GlbLayout {
  std::size_t jsonOffset = 0;
  std::size_t jsonLength = 0;
  bool hasBin = false;
  std::size_t binOffset = 0;
  std::size_t binLength = 0;
};

// True when the bytes start with the GLB magic "glTF".
bool hasGlbMagic(std::span<const std::uint8_t> bytes);

// Validates the 12-byte header (magic, version 2, length equal to the file size) and the chunk
// table (JSON first, then an optional BIN chunk, each inside the file). Throws engine::Error
// describing the fault (without the file name; the caller adds it).
GlbLayout parseGlbLayout(std::span<const std::uint8_t> bytes);

}  // namespace engine::assets::gltf
