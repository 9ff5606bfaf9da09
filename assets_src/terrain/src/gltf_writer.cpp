#include "gltf_writer.h"

#include <bit>
#include <cstring>
#include <string>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/file_io.h"

namespace terrain {
namespace {

// glTF buffers are little-endian; the vertex arrays are copied from memory as they are.
static_assert(std::endian::native == std::endian::little, "glTF buffers must be little-endian");

// glTF enumerations (glTF 2.0 spec, section 5).
constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;

using Json = nlohmann::ordered_json;

/// Appends arrays to one binary buffer and records a bufferView and an accessor for each.
class BufferBuilder {
 public:
  template <typename T>
  int add(const std::vector<T>& data, const char* type, int componentType, int target) {
    // Every element type here is 4-byte aligned; keep each view's offset so too.
    while (bytes_.size() % 4 != 0) bytes_.push_back('\0');
    const std::size_t offset = bytes_.size();
    const std::size_t size = data.size() * sizeof(T);
    bytes_.resize(offset + size);
    if (size != 0) std::memcpy(bytes_.data() + offset, data.data(), size);

    views_.push_back(
        Json{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
    accessors_.push_back(Json{{"bufferView", views_.size() - 1},
                              {"componentType", componentType},
                              {"count", data.size()},
                              {"type", type}});
    return static_cast<int>(accessors_.size() - 1);
  }

  Json& accessor(int index) { return accessors_[static_cast<std::size_t>(index)]; }
  const std::string& bytes() const { return bytes_; }
  const Json& views() const { return views_; }
  const Json& accessors() const { return accessors_; }

 private:
  std::string bytes_;
  Json views_ = Json::array();
  Json accessors_ = Json::array();
};

Json jsonVec3(const glm::vec3& v) {
  return Json::array({v.x, v.y, v.z});
}

}  // namespace

void writeTerrainGltf(const TerrainMesh& mesh, const CoverRules& rules,
                      const std::filesystem::path& gltfPath) {
  if (gltfPath.extension() != ".gltf") {
    throw engine::Error(gltfPath.string() + ": output file name must end in .gltf");
  }
  std::filesystem::path binPath = gltfPath;
  binPath.replace_extension(".bin");

  BufferBuilder buffer;
  const int position = buffer.add(mesh.positions, "VEC3", kFloat, kArrayBuffer);
  const int normal = buffer.add(mesh.normals, "VEC3", kFloat, kArrayBuffer);
  const int uv = buffer.add(mesh.uvs, "VEC2", kFloat, kArrayBuffer);
  const int colour = buffer.add(mesh.colours, "VEC3", kFloat, kArrayBuffer);
  const int indices = buffer.add(mesh.indices, "SCALAR", kUnsignedInt, kElementArrayBuffer);

  // POSITION must carry its bounds (glTF 2.0, 3.6.2.4); they are the exact float values.
  glm::vec3 lo = mesh.positions.empty() ? glm::vec3(0.0f) : mesh.positions.front();
  glm::vec3 hi = lo;
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  buffer.accessor(position)["min"] = jsonVec3(lo);
  buffer.accessor(position)["max"] = jsonVec3(hi);

  Json gltf;
  gltf["asset"] = {{"version", "2.0"}, {"generator", "cloudscape terrain_gen"}};
  gltf["scene"] = 0;
  gltf["scenes"] = Json::array({Json{{"name", "terrain"}, {"nodes", Json::array({0})}}});
  gltf["nodes"] = Json::array({Json{{"name", "terrain"}, {"mesh", 0}}});
  gltf["materials"] = Json::array({Json{{"name", "terrain"},
                                        {"pbrMetallicRoughness",
                                         {{"baseColorFactor", {1.0, 1.0, 1.0, 1.0}},
                                          {"metallicFactor", 0.0},
                                          {"roughnessFactor", 1.0}}}}});
  Json primitive = {
      {"attributes",
       {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}, {"COLOR_0", colour}}},
      {"indices", indices},
      {"material", 0},
      {"mode", kTriangles}};
  gltf["meshes"] = Json::array({Json{{"name", "terrain"},
                                     {"primitives", Json::array({primitive})},
                                     {"extras",
                                      {{kCoverPaletteExtras,
                                        {{"grass", jsonVec3(rules.grassColour)},
                                         {"rock", jsonVec3(rules.rockColour)},
                                         {"snow", jsonVec3(rules.snowColour)}}}}}}});
  gltf["accessors"] = buffer.accessors();
  gltf["bufferViews"] = buffer.views();
  gltf["buffers"] = Json::array(
      {Json{{"uri", binPath.filename().string()}, {"byteLength", buffer.bytes().size()}}});

  // writeTextFile opens in binary mode, so the buffer's bytes go out unchanged.
  engine::writeTextFile(binPath, buffer.bytes());
  engine::writeTextFile(gltfPath, gltf.dump(2) + "\n");
}

}  // namespace terrain
