#pragma once
// Runs tinygltf over already-validated bytes with the confined file system and without image
// decoding. Nothing in the returned model is range-checked yet.
#include <cstdint>
#include <span>

#include <tiny_gltf.h>

#include "gltf_asset_folder.h"
#include "gltf_container.h"

namespace engine::assets::gltf {

// Parses a .gltf (`glb` null) or a .glb whose layout parseGlbLayout accepted. Images given by
// URI keep their undecoded file bytes in Image::image (with as_is set); images given by
// bufferView stay untouched. Throws engine::Error "glTF parse failed: ..." on any tinygltf error
// or exception.
tinygltf::Model parseGltf(std::span<const std::uint8_t> bytes, const GlbLayout* glb,
                          AssetFolder& folder);

}  // namespace engine::assets::gltf
