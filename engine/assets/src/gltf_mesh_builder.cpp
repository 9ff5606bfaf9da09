#include "gltf_mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "engine/core/error.h"
#include "gltf_accessor.h"
#include "gltf_checked_math.h"

namespace engine::assets::gltf {
namespace {

// Indices are 32-bit, so the whole mesh may hold at most 2^32 - 1 vertices whatever the limits.
constexpr std::uint64_t kMaxIndexableVertices = std::numeric_limits<std::uint32_t>::max();

constexpr glm::vec3 kFallbackNormal{0.0f, 1.0f, 0.0f};  // for degenerate geometry: up

bool isFinite(const glm::vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

std::string elementName(const AccessorView& view, std::size_t i) {
  return "accessor " + std::to_string(view.index) + " (" + semanticName(view.semantic) +
         "): element " + std::to_string(i);
}

glm::vec4 finiteElement(const AccessorView& view, std::size_t i) {
  const glm::vec4 v = view.element(i);
  if (!isFinite(v)) throw Error(elementName(view, i) + " is not finite (NaN or Inf)");
  return v;
}

std::optional<AccessorView> optionalAttribute(const tinygltf::Model& model,
                                              const tinygltf::Primitive& primitive,
                                              const char* name, Semantic semantic,
                                              std::size_t vertexCount) {
  const auto it = primitive.attributes.find(name);
  if (it == primitive.attributes.end()) return std::nullopt;
  AccessorView view = validateAccessor(model, it->second, semantic, vertexCount);
  if (view.count != vertexCount) {
    throw Error("accessor " + std::to_string(view.index) + " (" + name + "): count " +
                std::to_string(view.count) + " differs from POSITION's " +
                std::to_string(vertexCount));
  }
  return view;
}

// The inverse-transpose of the linear part up to a positive scale (removed by normalising):
// the cofactor matrix, whose columns are these cross products, equals inverse-transpose times
// the determinant, so its sign is corrected for mirroring transforms. Unlike the inverse it is
// defined for singular transforms too.
glm::dmat3 normalMatrix(const glm::dmat4& world) {
  const glm::dvec3 c0(world[0]), c1(world[1]), c2(world[2]);
  const glm::dmat3 cofactor(glm::cross(c1, c2), glm::cross(c2, c0), glm::cross(c0, c1));
  return glm::determinant(glm::dmat3(world)) < 0.0 ? -cofactor : cofactor;
}

glm::vec3 normalizedOr(const glm::dvec3& v, const glm::vec3& fallback) {
  const double length = glm::length(v);
  if (!(length > 1e-30) || !std::isfinite(length)) return fallback;
  return glm::vec3(v / length);
}

}  // namespace

MeshBuilder::MeshBuilder(const tinygltf::Model& model, const GltfLimits& limits)
    : model_(model), limits_(limits) {}

void MeshBuilder::addInstance(const MeshInstance& instance) {
  const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(instance.mesh)];
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = mesh.primitives[p];
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES) continue;
    addPrimitive(primitive, instance,
                 "mesh " + std::to_string(instance.mesh) + " primitive " + std::to_string(p) +
                     " (node " + std::to_string(instance.node) + ")");
  }
}

glm::vec4 MeshBuilder::baseColorFactor(int material, const std::string& where) const {
  if (material == -1) return glm::vec4(1.0f);
  if (material < 0 || static_cast<std::size_t>(material) >= model_.materials.size()) {
    throw Error(where + ": material " + std::to_string(material) + " is out of range (" +
                std::to_string(model_.materials.size()) + " materials)");
  }
  const std::vector<double>& factor =
      model_.materials[static_cast<std::size_t>(material)].pbrMetallicRoughness.baseColorFactor;
  if (factor.size() != 4 ||
      !std::all_of(factor.begin(), factor.end(), [](double v) { return std::isfinite(v); })) {
    throw Error("material " + std::to_string(material) +
                ": baseColorFactor must be 4 finite numbers");
  }
  return glm::vec4(glm::dvec4(factor[0], factor[1], factor[2], factor[3]));
}

void MeshBuilder::addPrimitive(const tinygltf::Primitive& primitive, const MeshInstance& instance,
                               const std::string& where) {
  // --- Validate every range, count, index and the material before reading vertex values.
  // Values are checked (finite) while appending; any error abandons the whole load.
  const auto positionIt = primitive.attributes.find("POSITION");
  if (positionIt == primitive.attributes.end()) throw Error(where + " has no POSITION attribute");
  const AccessorView positions =
      validateAccessor(model_, positionIt->second, Semantic::Position, limits_.maxTotalVertices);
  const std::size_t vertexCount = positions.count;
  const std::size_t base = mesh_.positions.size();
  const std::uint64_t totalVertices = checkedAdd(base, vertexCount);
  if (totalVertices > limits_.maxTotalVertices || totalVertices > kMaxIndexableVertices) {
    throw Error(where + ": " + std::to_string(totalVertices) +
                " vertices in total, over the limit of " +
                std::to_string(std::min(limits_.maxTotalVertices, kMaxIndexableVertices)));
  }

  const auto normals =
      optionalAttribute(model_, primitive, "NORMAL", Semantic::Normal, vertexCount);
  const auto uvs =
      optionalAttribute(model_, primitive, "TEXCOORD_0", Semantic::TexCoord, vertexCount);
  const auto colors = optionalAttribute(model_, primitive, "COLOR_0", Semantic::Color, vertexCount);

  std::optional<AccessorView> indexView;
  std::size_t indexCount = vertexCount;
  if (primitive.indices != -1) {
    indexView =
        validateAccessor(model_, primitive.indices, Semantic::Indices, limits_.maxTotalIndices);
    indexCount = indexView->count;
  }
  if (indexCount % 3 != 0) {
    throw Error(where + ": " + std::to_string(indexCount) +
                (indexView ? " indices" : " vertices (no indices)") +
                " do not form whole triangles");
  }
  const std::uint64_t totalIndices = checkedAdd(mesh_.indices.size(), indexCount);
  if (totalIndices > limits_.maxTotalIndices) {
    throw Error(where + ": " + std::to_string(totalIndices) +
                " indices in total, over the limit of " + std::to_string(limits_.maxTotalIndices));
  }
  std::vector<std::uint32_t> indices(indexCount);
  for (std::size_t i = 0; i < indexCount; ++i) {
    indices[i] = indexView ? indexView->indexAt(i) : static_cast<std::uint32_t>(i);
    if (indices[i] >= vertexCount) {
      throw Error(elementName(*indexView, i) + ": index " + std::to_string(indices[i]) +
                  " is >= the primitive's vertex count " + std::to_string(vertexCount));
    }
  }
  const glm::vec4 factor = baseColorFactor(primitive.material, where);

  // --- Append. A mirroring transform turns counter-clockwise triangles clockwise; swapping two
  // corners restores the winding (glTF spec, "Transformations").
  const glm::dmat4& world = instance.world;
  const glm::dmat3 normalTransform = normalMatrix(world);
  const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
  for (std::size_t i = 0; i < vertexCount; ++i) {
    const glm::dvec4 p =
        world * glm::dvec4(glm::dvec3(glm::vec3(finiteElement(positions, i))), 1.0);
    const glm::vec3 worldPosition(p);
    if (!isFinite(glm::vec4(worldPosition, 1.0f))) {
      throw Error(elementName(positions, i) + " is not finite after node " +
                  std::to_string(instance.node) + "'s transform");
    }
    mesh_.positions.push_back(worldPosition);
    mesh_.normals.push_back(
        normals ? normalizedOr(normalTransform * glm::dvec3(glm::vec3(finiteElement(*normals, i))),
                               kFallbackNormal)
                : glm::vec3(0.0f));
    mesh_.uvs.push_back(uvs ? glm::vec2(finiteElement(*uvs, i)) : glm::vec2(0.0f));
    mesh_.colors.push_back((colors ? finiteElement(*colors, i) : glm::vec4(1.0f)) * factor);
  }
  const std::size_t firstIndex = mesh_.indices.size();
  for (std::size_t t = 0; t < indexCount; t += 3) {
    const std::uint32_t b = static_cast<std::uint32_t>(base);
    mesh_.indices.push_back(b + indices[t]);
    mesh_.indices.push_back(b + indices[mirrored ? t + 2 : t + 1]);
    mesh_.indices.push_back(b + indices[mirrored ? t + 1 : t + 2]);
  }

  if (!normals) {
    // Unnormalised face normals have length twice the triangle's area: summing them weights
    // each face by its area.
    std::vector<glm::dvec3> sums(vertexCount, glm::dvec3(0.0));
    for (std::size_t t = firstIndex; t < mesh_.indices.size(); t += 3) {
      const std::uint32_t a = mesh_.indices[t], b = mesh_.indices[t + 1], c = mesh_.indices[t + 2];
      const glm::dvec3 pa(mesh_.positions[a]), pb(mesh_.positions[b]), pc(mesh_.positions[c]);
      const glm::dvec3 face = glm::cross(pb - pa, pc - pa);
      sums[a - base] += face;
      sums[b - base] += face;
      sums[c - base] += face;
    }
    for (std::size_t i = 0; i < vertexCount; ++i) {
      mesh_.normals[base + i] = normalizedOr(sums[i], kFallbackNormal);
    }
  }
}

MeshData MeshBuilder::finish() {
  if (mesh_.indices.empty()) throw Error("no triangle primitives reachable from the scene");
  mesh_.boundsMin = mesh_.boundsMax = mesh_.positions.front();
  for (const glm::vec3& p : mesh_.positions) {
    mesh_.boundsMin = glm::min(mesh_.boundsMin, p);
    mesh_.boundsMax = glm::max(mesh_.boundsMax, p);
  }
  return std::move(mesh_);
}

}  // namespace engine::assets::gltf
