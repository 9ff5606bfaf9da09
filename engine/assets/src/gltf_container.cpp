#include "gltf_container.h"

#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "gltf_checked_math.h"

namespace engine::assets::gltf {
namespace {

constexpr std::uint32_t kJsonChunk = 0x4E4F534Au;  // "JSON" little-endian
constexpr std::uint32_t kBinChunk = 0x004E4942u;   // "BIN\0" little-endian
constexpr std::size_t kHeaderBytes = 12;
constexpr std::size_t kChunkHeaderBytes = 8;

// GLB fields are little-endian, as is every target this engine builds for.
std::uint32_t readU32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value;
}

std::string hex(std::uint32_t value) {
  static const char* digits = "0123456789abcdef";
  std::string out = "0x";
  for (int shift = 28; shift >= 0; shift -= 4) out += digits[(value >> shift) & 0xFu];
  return out;
}

}  // namespace

bool hasGlbMagic(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

GlbLayout parseGlbLayout(std::span<const std::uint8_t> bytes) {
  const std::size_t size = bytes.size();
  if (size < kHeaderBytes) {
    throw Error("GLB truncated: " + std::to_string(size) + " bytes, shorter than the " +
                std::to_string(kHeaderBytes) + "-byte header");
  }
  if (!hasGlbMagic(bytes)) throw Error("not a GLB file (bad magic, expected \"glTF\")");
  const std::uint32_t version = readU32(bytes, 4);
  if (version != 2) {
    throw Error("GLB version " + std::to_string(version) + " is not supported (need 2)");
  }
  const std::uint32_t declared = readU32(bytes, 8);
  if (declared != size) {
    throw Error("GLB header length " + std::to_string(declared) + " does not match the file size " +
                std::to_string(size));
  }
  if (size < kHeaderBytes + kChunkHeaderBytes) {
    throw Error("GLB truncated: no JSON chunk header after the 12-byte header");
  }

  GlbLayout layout;
  std::size_t offset = kHeaderBytes;
  int chunkIndex = 0;
  while (offset < size) {
    if (!rangeFits(offset, kChunkHeaderBytes, size)) {
      throw Error("GLB truncated: chunk " + std::to_string(chunkIndex) + " header at byte " +
                  std::to_string(offset) + " runs past the end of the file");
    }
    const std::uint32_t length = readU32(bytes, offset);
    const std::uint32_t type = readU32(bytes, offset + 4);
    const std::size_t dataOffset = offset + kChunkHeaderBytes;
    if (!rangeFits(dataOffset, length, size)) {
      throw Error("GLB chunk " + std::to_string(chunkIndex) + " length " + std::to_string(length) +
                  " runs past the end of the file (" + std::to_string(size - dataOffset) +
                  " bytes left)");
    }
    if (chunkIndex == 0) {
      if (type != kJsonChunk) {
        throw Error("GLB chunk 0 has type " + hex(type) + ", expected JSON");
      }
      if (length == 0) throw Error("GLB JSON chunk is empty");
      layout.jsonOffset = dataOffset;
      layout.jsonLength = length;
    } else if (chunkIndex == 1 && type == kBinChunk) {
      // tinygltf rejects unaligned BIN chunks; say so here with the offending length.
      if (length % 4 != 0) {
        throw Error("GLB BIN chunk length " + std::to_string(length) + " is not a multiple of 4");
      }
      layout.hasBin = true;
      layout.binOffset = dataOffset;
      layout.binLength = length;
    } else if (chunkIndex == 1) {
      // tinygltf reads the second chunk as BIN whatever its type; refuse instead of guessing.
      throw Error("GLB chunk 1 has type " + hex(type) + ", expected BIN");
    }
    // Chunks after BIN are extensions' business; they only need to lie inside the file.
    offset = dataOffset + length;
    ++chunkIndex;
  }
  return layout;
}

}  // namespace engine::assets::gltf
