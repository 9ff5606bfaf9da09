// libFuzzer target: the glTF loader on .gltf (JSON with data: URIs) and .glb input. Which of
// the two is chosen by the input's first bytes, as a user's file would be named: "glTF" magic
// is a .glb, anything else a .gltf.
#include <cstring>

#include "engine/assets/gltf_loader.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Small limits: a finding should be a wrong read, not a slow large allocation.
  engine::assets::GltfLimits limits;
  limits.maxFileBytes = 1u << 20;
  limits.maxTotalVertices = 1u << 16;
  limits.maxTotalIndices = 1u << 18;
  limits.maxTotalExternalBytes = 1u << 20;
  const auto load = [&](const std::filesystem::path& file) {
    engine::assets::loadGltfMesh(file, limits);
  };
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  return fuzz::loadInput(binary ? ".glb" : ".gltf", data, size, load);
}
