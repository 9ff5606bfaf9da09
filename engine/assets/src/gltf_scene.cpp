#include "gltf_scene.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "engine/core/error.h"

namespace engine::assets::gltf {
namespace {

std::string nodeName(std::size_t index) {
  return "node " + std::to_string(index);
}

void requireFinite(const std::vector<double>& values, std::size_t node, const char* field) {
  if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) {
    throw Error(nodeName(node) + ": " + field + " has a non-finite value");
  }
}

void requireSize(const std::vector<double>& values, std::size_t expected, std::size_t node,
                 const char* field) {
  if (!values.empty() && values.size() != expected) {
    throw Error(nodeName(node) + ": " + field + " has " + std::to_string(values.size()) +
                " values, expected " + std::to_string(expected));
  }
  requireFinite(values, node, field);
}

glm::dmat4 localTransform(const tinygltf::Node& node, std::size_t index) {
  if (!node.matrix.empty()) {
    requireSize(node.matrix, 16, index, "matrix");
    return glm::make_mat4(node.matrix.data());  // glTF matrices are column-major, as is GLM
  }
  requireSize(node.translation, 3, index, "translation");
  requireSize(node.rotation, 4, index, "rotation");
  requireSize(node.scale, 3, index, "scale");
  glm::dmat4 m(1.0);
  if (!node.translation.empty()) {
    m = glm::translate(m,
                       glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (!node.rotation.empty()) {
    // glTF stores (x, y, z, w); GLM's constructor takes w first.
    glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const double length = glm::length(q);
    if (!(length > 1e-12)) throw Error(nodeName(index) + ": rotation is a zero quaternion");
    m *= glm::mat4_cast(q / length);
  }
  if (!node.scale.empty()) {
    m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  }
  return m;
}

std::vector<int> sceneRoots(const tinygltf::Model& model, const std::vector<int>& parent) {
  std::vector<int> roots;
  if (model.scenes.empty()) {
    if (model.defaultScene >= 0) {
      throw Error("scene " + std::to_string(model.defaultScene) + " is out of range (0 scenes)");
    }
    for (std::size_t i = 0; i < parent.size(); ++i) {
      if (parent[i] < 0) roots.push_back(static_cast<int>(i));
    }
    return roots;
  }
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (static_cast<std::size_t>(sceneIndex) >= model.scenes.size()) {
    throw Error("scene " + std::to_string(sceneIndex) + " is out of range (" +
                std::to_string(model.scenes.size()) + " scenes)");
  }
  const std::string sceneName = "scene " + std::to_string(sceneIndex);
  std::vector<bool> listed(parent.size(), false);
  for (const int n : model.scenes[static_cast<std::size_t>(sceneIndex)].nodes) {
    if (n < 0 || static_cast<std::size_t>(n) >= parent.size()) {
      throw Error(sceneName + ": node " + std::to_string(n) + " is out of range (" +
                  std::to_string(parent.size()) + " nodes)");
    }
    const auto i = static_cast<std::size_t>(n);
    if (parent[i] >= 0) {
      throw Error(sceneName + ": node " + std::to_string(n) + " is not a root (it is a child of " +
                  nodeName(static_cast<std::size_t>(parent[i])) + ")");
    }
    // Listing a root twice would duplicate its whole subtree.
    if (listed[i]) throw Error(sceneName + " lists node " + std::to_string(n) + " twice");
    listed[i] = true;
    roots.push_back(n);
  }
  return roots;
}

}  // namespace

std::vector<MeshInstance> collectMeshInstances(const tinygltf::Model& model) {
  const std::size_t nodeCount = model.nodes.size();
  std::vector<int> parent(nodeCount, -1);
  std::vector<glm::dmat4> local(nodeCount);
  for (std::size_t i = 0; i < nodeCount; ++i) {
    const tinygltf::Node& node = model.nodes[i];
    if (node.mesh < -1 ||
        (node.mesh >= 0 && static_cast<std::size_t>(node.mesh) >= model.meshes.size())) {
      throw Error(nodeName(i) + ": mesh " + std::to_string(node.mesh) + " is out of range (" +
                  std::to_string(model.meshes.size()) + " meshes)");
    }
    for (const int child : node.children) {
      if (child < 0 || static_cast<std::size_t>(child) >= nodeCount) {
        throw Error(nodeName(i) + ": child " + std::to_string(child) + " is out of range (" +
                    std::to_string(nodeCount) + " nodes)");
      }
      const auto c = static_cast<std::size_t>(child);
      if (c == i) throw Error(nodeName(i) + " is its own child (cycle in the node hierarchy)");
      // A node shared by two parents would be visited once per path: exponential in a chain of
      // diamonds. glTF requires a forest.
      if (parent[c] >= 0) {
        throw Error(nodeName(c) + " has more than one parent (" +
                    nodeName(static_cast<std::size_t>(parent[c])) + " and " + nodeName(i) + ")");
      }
      parent[c] = static_cast<int>(i);
    }
    local[i] = localTransform(node, i);
  }

  // With at most one parent each, a node is unreachable from every root only through a cycle.
  std::vector<bool> reachable(nodeCount, false);
  std::vector<std::size_t> stack;
  for (std::size_t i = 0; i < nodeCount; ++i) {
    if (parent[i] < 0) stack.push_back(i);
  }
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    reachable[i] = true;
    for (const int child : model.nodes[i].children)
      stack.push_back(static_cast<std::size_t>(child));
  }
  for (std::size_t i = 0; i < nodeCount; ++i) {
    if (!reachable[i]) {
      throw Error(nodeName(i) + " is in a cycle of the node hierarchy (no root reaches it)");
    }
  }

  std::vector<MeshInstance> instances;
  std::vector<std::pair<std::size_t, glm::dmat4>> pending;
  for (const int root : sceneRoots(model, parent)) {
    pending.emplace_back(static_cast<std::size_t>(root), glm::dmat4(1.0));
    while (!pending.empty()) {
      auto [i, parentWorld] = pending.back();
      pending.pop_back();
      const glm::dmat4 world = parentWorld * local[i];
      const tinygltf::Node& node = model.nodes[i];
      if (node.mesh >= 0) instances.push_back({static_cast<int>(i), node.mesh, world});
      // Reverse so children come off the stack in the file's order.
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
        pending.emplace_back(static_cast<std::size_t>(*it), world);
      }
    }
  }
  return instances;
}

}  // namespace engine::assets::gltf
