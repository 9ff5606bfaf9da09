#include "gltf_reader.h"

#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/file_io.h"
#include "gltf_writer.h"

namespace terrain {
namespace {

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;

using Json = nlohmann::json;

/// The glTF document and its single buffer, with messages that name the file.
class GltfFile {
 public:
  explicit GltfFile(const std::filesystem::path& path) : file_(path.string()) {
    try {
      json_ = Json::parse(engine::readTextFile(path));
    } catch (const Json::parse_error& e) {
      fail("", std::string("invalid JSON: ") + e.what());
    }
    const Json& version = get(get(json_, "asset", "asset"), "version", "asset.version");
    if (version != "2.0") fail("asset.version", "must be \"2.0\", got " + version.dump());
    const Json& buffers = get(json_, "buffers", "buffers");
    if (!buffers.is_array() || buffers.size() != 1) fail("buffers", "must hold exactly one buffer");
    const Json& uri = get(buffers[0], "uri", "buffers[0].uri");
    if (!uri.is_string()) fail("buffers[0].uri", "must be a file name");
    bin_ = engine::readBinaryFile(path.parent_path() / uri.get<std::string>());
    const Json& length = get(buffers[0], "byteLength", "buffers[0].byteLength");
    if (!length.is_number_unsigned() || length.get<std::size_t>() != bin_.size()) {
      fail("buffers[0].byteLength", length.dump() + " does not match the " +
                                        std::to_string(bin_.size()) + "-byte file " +
                                        uri.get<std::string>());
    }
  }

  [[noreturn]] void fail(const std::string& where, const std::string& why) const {
    throw engine::Error(file_ + ": " + (where.empty() ? why : where + ": " + why));
  }

  const Json& get(const Json& object, const char* key, const std::string& where) const {
    if (!object.is_object() || !object.contains(key)) fail(where, "missing");
    return object.at(key);
  }

  std::size_t index(const Json& value, const std::string& where) const {
    if (!value.is_number_unsigned()) fail(where, "must be a non-negative integer");
    return value.get<std::size_t>();
  }

  const Json& element(const char* array, std::size_t i) const {
    const Json& items = get(json_, array, array);
    if (!items.is_array() || i >= items.size()) {
      fail(std::string(array) + "[" + std::to_string(i) + "]", "does not exist");
    }
    return items[i];
  }

  /// Copies accessor `a` into `out`, checking it holds `type`/`componentType` elements of T.
  template <typename T>
  void readAccessor(std::size_t a, const char* type, int componentType, std::vector<T>& out) const {
    const std::string where = "accessors[" + std::to_string(a) + "]";
    const Json& accessor = element("accessors", a);
    if (get(accessor, "type", where + ".type") != type)
      fail(where + ".type", "must be " + std::string(type));
    if (get(accessor, "componentType", where + ".componentType") != componentType) {
      fail(where + ".componentType", "must be " + std::to_string(componentType));
    }
    const std::size_t count = index(get(accessor, "count", where + ".count"), where + ".count");
    const std::size_t viewIndex =
        index(get(accessor, "bufferView", where + ".bufferView"), where + ".bufferView");
    const std::size_t accessorOffset =
        accessor.contains("byteOffset") ? index(accessor["byteOffset"], where + ".byteOffset") : 0;

    const std::string viewWhere = "bufferViews[" + std::to_string(viewIndex) + "]";
    const Json& view = element("bufferViews", viewIndex);
    const std::size_t viewOffset =
        view.contains("byteOffset") ? index(view["byteOffset"], viewWhere + ".byteOffset") : 0;
    const std::size_t viewLength =
        index(get(view, "byteLength", viewWhere + ".byteLength"), viewWhere + ".byteLength");
    if (view.contains("byteStride") && view["byteStride"] != sizeof(T)) {
      fail(viewWhere + ".byteStride", "must be absent or " + std::to_string(sizeof(T)));
    }
    if (viewOffset > bin_.size() || viewLength > bin_.size() - viewOffset) {
      fail(viewWhere, "runs past the end of the buffer");
    }
    if (count > (viewLength - std::min(accessorOffset, viewLength)) / sizeof(T)) {
      fail(where, "runs past the end of " + viewWhere);
    }
    out.resize(count);
    if (count != 0)
      std::memcpy(out.data(), bin_.data() + viewOffset + accessorOffset, count * sizeof(T));
  }

  glm::vec3 vec3(const Json& value, const std::string& where) const {
    if (!value.is_array() || value.size() != 3) fail(where, "must be an array of three numbers");
    glm::vec3 v(0.0f);
    for (glm::vec3::length_type i = 0; i < 3; ++i) {
      const Json& c = value[static_cast<std::size_t>(i)];
      if (!c.is_number()) fail(where, "must be an array of three numbers");
      v[i] = c.get<float>();
    }
    return v;
  }

  const Json& json() const { return json_; }

 private:
  std::string file_;
  Json json_;
  std::vector<std::uint8_t> bin_;
};

}  // namespace

LoadedTerrain readTerrainGltf(const std::filesystem::path& gltfPath) {
  const GltfFile gltf(gltfPath);
  const Json& meshes = gltf.get(gltf.json(), "meshes", "meshes");
  if (!meshes.is_array() || meshes.size() != 1) gltf.fail("meshes", "must hold exactly one mesh");
  const Json& primitives = gltf.get(meshes[0], "primitives", "meshes[0].primitives");
  if (!primitives.is_array() || primitives.size() != 1) {
    gltf.fail("meshes[0].primitives", "must hold exactly one primitive");
  }
  const Json& primitive = primitives[0];
  const std::string where = "meshes[0].primitives[0]";
  if (primitive.contains("mode") && primitive["mode"] != 4)
    gltf.fail(where + ".mode", "must be 4 (triangles)");
  const Json& attributes = gltf.get(primitive, "attributes", where + ".attributes");
  const auto attribute = [&](const char* name) {
    const std::string at = where + ".attributes." + name;
    return gltf.index(gltf.get(attributes, name, at), at);
  };

  LoadedTerrain loaded;
  TerrainMesh& mesh = loaded.mesh;
  const std::size_t position = attribute("POSITION");
  gltf.readAccessor(position, "VEC3", kFloat, mesh.positions);
  gltf.readAccessor(attribute("NORMAL"), "VEC3", kFloat, mesh.normals);
  gltf.readAccessor(attribute("TEXCOORD_0"), "VEC2", kFloat, mesh.uvs);
  gltf.readAccessor(attribute("COLOR_0"), "VEC3", kFloat, mesh.colours);
  gltf.readAccessor(
      gltf.index(gltf.get(primitive, "indices", where + ".indices"), where + ".indices"), "SCALAR",
      kUnsignedInt, mesh.indices);

  const Json& positionAccessor = gltf.element("accessors", position);
  const std::string positionWhere = "accessors[" + std::to_string(position) + "]";
  loaded.declaredMin =
      gltf.vec3(gltf.get(positionAccessor, "min", positionWhere + ".min"), positionWhere + ".min");
  loaded.declaredMax =
      gltf.vec3(gltf.get(positionAccessor, "max", positionWhere + ".max"), positionWhere + ".max");

  // The palette is optional: without it the check still runs, minus the cover shares.
  const Json& extras = meshes[0].value("extras", Json::object());
  if (extras.is_object() && extras.contains(kCoverPaletteExtras)) {
    const Json& p = extras[kCoverPaletteExtras];
    const std::string at = std::string("meshes[0].extras.") + kCoverPaletteExtras;
    loaded.palette = CoverPalette{gltf.vec3(gltf.get(p, "grass", at + ".grass"), at + ".grass"),
                                  gltf.vec3(gltf.get(p, "rock", at + ".rock"), at + ".rock"),
                                  gltf.vec3(gltf.get(p, "snow", at + ".snow"), at + ".snow")};
  }
  return loaded;
}

}  // namespace terrain
