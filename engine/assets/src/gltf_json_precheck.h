#pragma once
// Checks on the raw glTF JSON for what tinygltf acts on while parsing (opening URIs, copying
// the BIN chunk per buffer, recursing into extras), done before tinygltf sees the JSON.
#include <string_view>

#include "gltf_asset_folder.h"

namespace engine::assets::gltf {

// Refuses: invalid JSON or nesting deeper than 64 levels; a buffer without a uri unless it is
// buffer 0 of a .glb that has a BIN chunk; a uri that is not a string, an unsupported data: URI,
// or any other uri AssetFolder::checkUri refuses; external files summing over `maxTotalBytes`;
// a bufferView byteStride outside 4..252 or not a multiple of 4. Throws engine::Error naming
// the buffer/image/bufferView index.
void precheckGltfJson(std::string_view json, bool isGlb, bool glbHasBin, const AssetFolder& folder,
                      std::uint64_t maxTotalBytes);

}  // namespace engine::assets::gltf
