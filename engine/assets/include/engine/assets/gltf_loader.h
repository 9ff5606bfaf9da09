#pragma once
// glTF 2.0 (.gltf with external or data: buffers, and .glb) triangle meshes, loaded for
// untrusted input: every byte range, index, node link and URI is checked before the data it
// names is read, and memory use is bounded by GltfLimits. tinygltf parses the JSON but is never
// trusted with ranges: 2.7.0 accepts an accessor of 100 million vertices on a 12-byte buffer and
// hands stb an image whose bufferView lies past its buffer.
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/assets/image_io.h"

namespace engine::assets {

// Every triangle primitive of a glTF scene flattened into one indexed triangle list. All vertex
// arrays have the same length.
struct MeshData {
  std::vector<glm::vec3> positions;    // metres, node transforms applied, Y up (glTF convention)
  std::vector<glm::vec3> normals;      // unit; computed (area-weighted) when the file has none
  std::vector<glm::vec2> uvs;          // TEXCOORD_0 or zeros
  std::vector<glm::vec4> colors;       // COLOR_0 (or white) times the material's baseColorFactor
  std::vector<std::uint32_t> indices;  // triangle list over all primitives, counter-clockwise
  glm::vec3 boundsMin{0.0f};
  glm::vec3 boundsMax{0.0f};
  // The first material's base colour texture (PNG or JPEG), decoded only after its byte range
  // was validated; empty when absent.
  ImageRgba8 baseColorTexture;
};

// Caps on what one load may read or allocate. Exceeding any of them is an engine::Error.
struct GltfLimits {
  // The .gltf/.glb itself, each external buffer/image file, and the decoded base colour
  // texture (4 bytes per pixel).
  std::uint64_t maxFileBytes = 1ull << 30;
  std::uint64_t maxTotalVertices = 32u << 20;  // summed over every primitive instance
  std::uint64_t maxTotalIndices = 96u << 20;   // summed over every primitive instance
  // All external files together: several buffers naming one big file would otherwise each be
  // read in full.
  std::uint64_t maxTotalExternalBytes = 4ull << 30;
};

// Loads every triangle primitive of every mesh reachable from the default scene (scene 0 when
// the file names none, or all root nodes when it has no scenes), flattened into one MeshData.
// External URIs must be relative paths that stay inside the asset's folder, or base64 data:
// URIs. Throws engine::Error "<file>: <what is wrong, naming the accessor/bufferView/buffer/
// image/node index>" for anything malformed, missing or over the limits; sparse accessors and
// accessors without a bufferView are reported as unsupported.
MeshData loadGltfMesh(const std::filesystem::path& path, const GltfLimits& limits = {});

}  // namespace engine::assets
