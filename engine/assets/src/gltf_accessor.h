#pragma once
// Accessors checked against their bufferView and buffer before any element is read.
#include <cstddef>
#include <cstdint>

#include <tiny_gltf.h>
#include <glm/vec4.hpp>

namespace engine::assets::gltf {

// What an accessor feeds; decides which component types and element types are allowed.
enum class Semantic { Position, Normal, TexCoord, Color, Indices };

// Name used in messages ("POSITION", "indices", ...).
const char* semanticName(Semantic semantic);

// An accessor whose every element lies inside its buffer's data. Valid while the model lives.
struct AccessorView {
  int index = -1;
  Semantic semantic = Semantic::Position;
  const std::uint8_t* first = nullptr;  // element 0
  std::size_t count = 0;
  std::size_t stride = 0;  // bytes between elements
  int componentType = 0;
  int components = 0;  // 1 to 4

  // Component `c` of element `i`; integer types are normalised to [0, 1] (the only valid
  // reading for the unsigned colour/texcoord types allowed here). i < count, c < components.
  float component(std::size_t i, int c) const;
  // Element `i` with missing components 0 (and w 1 for colours).
  glm::vec4 element(std::size_t i) const;
  // Index element `i` as an unsigned integer (indices only).
  std::uint32_t indexAt(std::size_t i) const;
};

// Validates accessor `index` for `semantic`: index in range; not sparse; has a bufferView;
// component and element type allowed; 0 < count <= maxCount; bufferView and buffer indices in
// range; the view inside its buffer's actual data; stride 0 or within [element size, 252] and a
// multiple of the component size; the last element inside the view. All sums and products are
// overflow-checked. Throws engine::Error "accessor N (SEMANTIC): ...".
AccessorView validateAccessor(const tinygltf::Model& model, int index, Semantic semantic,
                              std::uint64_t maxCount);

}  // namespace engine::assets::gltf
