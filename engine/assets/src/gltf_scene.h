#pragma once
// The node hierarchy: validated as a forest and flattened to mesh instances with world
// transforms.
#include <vector>

#include <tiny_gltf.h>
#include <glm/mat4x4.hpp>

namespace engine::assets::gltf {

// One node that draws a mesh, with the product of the transforms from its scene root.
struct MeshInstance {
  int node = -1;
  int mesh = -1;
  glm::dmat4 world{1.0};
};

// Validates every node (children and mesh indices in range, at most one parent each, no
// cycles, matrix of 16 or translation/rotation/scale of 3/4/3 finite numbers, non-zero
// rotation) and the chosen scene (the default scene, else scene 0, else every root node when
// there are no scenes; its nodes in range, roots, listed once). Returns the mesh instances in
// depth-first order. Throws engine::Error naming the node or scene index.
std::vector<MeshInstance> collectMeshInstances(const tinygltf::Model& model);

}  // namespace engine::assets::gltf
