// loadGltfMesh: the order of checks is the point. Container and JSON checks run before
// tinygltf, which reads only confined files and decodes no image; the model's ranges are
// checked before any vertex is read; the texture is decoded last, from a checked range.
#include "engine/assets/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "engine/core/error.h"
#include "engine/core/file_io.h"
#include "gltf_asset_folder.h"
#include "gltf_container.h"
#include "gltf_json_precheck.h"
#include "gltf_mesh_builder.h"
#include "gltf_parse.h"
#include "gltf_scene.h"
#include "gltf_texture.h"

namespace engine::assets {
namespace {

// tinygltf takes lengths as unsigned int.
constexpr std::uint64_t kMaxParsableBytes = std::numeric_limits<std::uint32_t>::max();

bool hasGlbExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".glb";
}

MeshData loadValidated(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                       const GltfLimits& limits) {
  if (bytes.empty()) throw Error("file is empty");
  gltf::AssetFolder folder(path, limits.maxFileBytes, limits.maxTotalExternalBytes);

  std::optional<gltf::GlbLayout> glb;
  if (gltf::hasGlbMagic(bytes) || hasGlbExtension(path)) glb = gltf::parseGlbLayout(bytes);
  const std::string_view json =
      glb ? std::string_view(reinterpret_cast<const char*>(bytes.data()) + glb->jsonOffset,
                             glb->jsonLength)
          : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  gltf::precheckGltfJson(json, glb.has_value(), glb && glb->hasBin, folder,
                         limits.maxTotalExternalBytes);

  const tinygltf::Model model = gltf::parseGltf(bytes, glb ? &*glb : nullptr, folder);
  gltf::validateImageRanges(model);
  gltf::MeshBuilder builder(model, limits);
  for (const gltf::MeshInstance& instance : gltf::collectMeshInstances(model)) {
    builder.addInstance(instance);
  }
  MeshData mesh = builder.finish();
  mesh.baseColorTexture = gltf::loadBaseColorTexture(model, limits.maxFileBytes);
  return mesh;
}

}  // namespace

MeshData loadGltfMesh(const std::filesystem::path& path, const GltfLimits& limits) {
  // readBinaryFile's errors already name the file.
  const std::uint64_t cap = std::min(limits.maxFileBytes, kMaxParsableBytes);
  const std::vector<std::uint8_t> bytes = readBinaryFile(path, static_cast<std::size_t>(cap));
  try {
    return loadValidated(path, bytes, limits);
  } catch (const Error& e) {
    throw Error(path.string() + ": " + e.what());
  }
}

}  // namespace engine::assets
