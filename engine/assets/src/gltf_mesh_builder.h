#pragma once
// Gathers validated triangle primitives of mesh instances into one MeshData.
#include <cstdint>
#include <string>

#include <tiny_gltf.h>

#include "engine/assets/gltf_loader.h"
#include "gltf_scene.h"

namespace engine::assets::gltf {

class MeshBuilder {
 public:
  MeshBuilder(const tinygltf::Model& model, const GltfLimits& limits);

  // Appends every TRIANGLES primitive of the instance's mesh (other modes are skipped), with
  // positions and normals in world space. Each primitive's accessors, counts against POSITION,
  // index values, running totals against the limits and material are validated before any
  // vertex is read. Throws engine::Error naming the mesh/primitive or accessor; the builder is
  // then unusable.
  void addInstance(const MeshInstance& instance);

  // The gathered mesh with bounds filled in. Throws engine::Error when no triangle primitive
  // was added.
  MeshData finish();

 private:
  void addPrimitive(const tinygltf::Primitive& primitive, const MeshInstance& instance,
                    const std::string& where);
  glm::vec4 baseColorFactor(int material, const std::string& where) const;

  const tinygltf::Model& model_;
  GltfLimits limits_;
  MeshData mesh_;
};

}  // namespace engine::assets::gltf
