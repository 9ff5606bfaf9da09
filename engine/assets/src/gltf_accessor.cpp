#include "gltf_accessor.h"

#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "gltf_checked_math.h"

namespace engine::assets::gltf {
namespace {

constexpr std::uint64_t kMaxStride = 252;  // glTF's limit on bufferView.byteStride

std::uint64_t componentBytes(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

int elementComponents(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;  // matrices never feed a mesh attribute
  }
}

bool typeAllowed(Semantic semantic, int components, int componentType) {
  const bool isFloat = componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  const bool isUnorm = componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                       componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  switch (semantic) {
    case Semantic::Position:
    case Semantic::Normal:
      return components == 3 && isFloat;
    case Semantic::TexCoord:
      return components == 2 && (isFloat || isUnorm);
    case Semantic::Color:
      return (components == 3 || components == 4) && (isFloat || isUnorm);
    case Semantic::Indices:
      return components == 1 && (isUnorm || componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  }
  return false;
}

const char* expectedTypes(Semantic semantic) {
  switch (semantic) {
    case Semantic::Position:
    case Semantic::Normal:
      return "VEC3 of FLOAT";
    case Semantic::TexCoord:
      return "VEC2 of FLOAT, UNSIGNED_BYTE or UNSIGNED_SHORT";
    case Semantic::Color:
      return "VEC3 or VEC4 of FLOAT, UNSIGNED_BYTE or UNSIGNED_SHORT";
    case Semantic::Indices:
      return "SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT";
  }
  return "";
}

[[noreturn]] void throwError(const std::string& what, const std::string& message) {
  throw Error(what + ": " + message);
}

template <typename T>
T load(const std::uint8_t* at) {
  T value;
  std::memcpy(&value, at, sizeof value);  // elements need not be aligned in hostile files
  return value;
}

}  // namespace

const char* semanticName(Semantic semantic) {
  switch (semantic) {
    case Semantic::Position:
      return "POSITION";
    case Semantic::Normal:
      return "NORMAL";
    case Semantic::TexCoord:
      return "TEXCOORD_0";
    case Semantic::Color:
      return "COLOR_0";
    case Semantic::Indices:
      return "indices";
  }
  return "";
}

float AccessorView::component(std::size_t i, int c) const {
  const std::uint8_t* at =
      first + i * stride + static_cast<std::size_t>(c) * componentBytes(componentType);
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return load<float>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return static_cast<float>(load<std::uint8_t>(at)) / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return static_cast<float>(load<std::uint16_t>(at)) / 65535.0f;
    default:
      return 0.0f;  // validateAccessor admits no other type for float semantics
  }
}

glm::vec4 AccessorView::element(std::size_t i) const {
  glm::vec4 v(0.0f, 0.0f, 0.0f, semantic == Semantic::Color ? 1.0f : 0.0f);
  for (int c = 0; c < components; ++c) v[c] = component(i, c);
  return v;
}

std::uint32_t AccessorView::indexAt(std::size_t i) const {
  const std::uint8_t* at = first + i * stride;
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return load<std::uint8_t>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return load<std::uint16_t>(at);
    default:
      return load<std::uint32_t>(at);
  }
}

AccessorView validateAccessor(const tinygltf::Model& model, int index, Semantic semantic,
                              std::uint64_t maxCount) {
  const std::string what =
      "accessor " + std::to_string(index) + " (" + semanticName(semantic) + ")";
  auto fail = [&what](const std::string& message) { throwError(what, message); };

  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    fail("index out of range (" + std::to_string(model.accessors.size()) + " accessors)");
  }
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  if (accessor.sparse.isSparse) fail("sparse accessors are not supported");
  if (accessor.bufferView < 0) fail("has no bufferView (zero-filled accessors are not supported)");

  const int components = elementComponents(accessor.type);
  const std::uint64_t compBytes = componentBytes(accessor.componentType);
  if (compBytes == 0 || !typeAllowed(semantic, components, accessor.componentType)) {
    fail("type " + std::to_string(accessor.type) + " with componentType " +
         std::to_string(accessor.componentType) + " is not allowed (expected " +
         expectedTypes(semantic) + ")");
  }
  const std::uint64_t count = accessor.count;
  if (count == 0) fail("count is 0");
  if (count > maxCount) {
    fail("count " + std::to_string(count) + " is over the limit of " + std::to_string(maxCount));
  }

  const auto viewIndex = static_cast<std::size_t>(accessor.bufferView);
  if (viewIndex >= model.bufferViews.size()) {
    fail("bufferView " + std::to_string(accessor.bufferView) + " is out of range (" +
         std::to_string(model.bufferViews.size()) + " bufferViews)");
  }
  const tinygltf::BufferView& view = model.bufferViews[viewIndex];
  const std::string viewName = "bufferView " + std::to_string(viewIndex);
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    fail(viewName + ": buffer " + std::to_string(view.buffer) + " is out of range (" +
         std::to_string(model.buffers.size()) + " buffers)");
  }
  const tinygltf::Buffer& buffer = model.buffers[static_cast<std::size_t>(view.buffer)];
  if (!rangeFits(view.byteOffset, view.byteLength, buffer.data.size())) {
    fail(viewName + " (byteOffset " + std::to_string(view.byteOffset) + ", byteLength " +
         std::to_string(view.byteLength) + ") lies outside buffer " + std::to_string(view.buffer) +
         " (" + std::to_string(buffer.data.size()) + " bytes)");
  }

  const std::uint64_t elementBytes = compBytes * static_cast<std::uint64_t>(components);
  std::uint64_t stride = elementBytes;
  if (view.byteStride != 0) {
    stride = view.byteStride;
    if (stride < elementBytes) {
      fail(viewName + " byteStride " + std::to_string(stride) + " is smaller than the " +
           std::to_string(elementBytes) + "-byte element");
    }
    if (stride > kMaxStride || stride % compBytes != 0) {
      fail(viewName + " byteStride " + std::to_string(stride) +
           " is over 252 or not a multiple of the component size " + std::to_string(compBytes));
    }
  }

  // Last byte read: byteOffset + (count - 1) * stride + elementBytes, inside the view.
  const std::uint64_t end =
      checkedAdd(checkedAdd(accessor.byteOffset, checkedMul(count - 1, stride)), elementBytes);
  if (end > view.byteLength) {
    fail("byteOffset " + std::to_string(accessor.byteOffset) + " + " + std::to_string(count) +
         " elements of stride " + std::to_string(stride) + " runs past the end of " + viewName +
         " (" + std::to_string(view.byteLength) + " bytes)");
  }

  AccessorView result;
  result.index = index;
  result.semantic = semantic;
  result.first = buffer.data.data() + view.byteOffset + accessor.byteOffset;
  result.count = static_cast<std::size_t>(count);
  result.stride = static_cast<std::size_t>(stride);
  result.componentType = accessor.componentType;
  result.components = components;
  return result;
}

}  // namespace engine::assets::gltf
