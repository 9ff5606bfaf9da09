#include "gltf_json_precheck.h"

#include <nlohmann/json.hpp>

#include <string>

#include "engine/core/error.h"
#include "gltf_checked_math.h"

namespace engine::assets::gltf {
namespace {

using Json = nlohmann::json;

// tinygltf converts extras and extensions recursively; a deeply nested value would overflow
// its stack. Real assets nest a handful of levels.
constexpr int kMaxJsonDepth = 64;

Json parseBounded(std::string_view text) {
  Json::parser_callback_t limitDepth = [](int depth, Json::parse_event_t, Json&) {
    if (depth > kMaxJsonDepth) {
      throw Error("JSON nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    return true;
  };
  try {
    return Json::parse(text.begin(), text.end(), limitDepth);
  } catch (const Json::exception& e) {
    // The message quotes the last token read, which a hostile file can make huge.
    throw Error("JSON parse error: " + std::string(e.what()).substr(0, 300));
  }
}

const Json* arrayMember(const Json& root, const char* name) {
  const auto it = root.find(name);
  return it != root.end() && it->is_array() ? &*it : nullptr;
}

// Returns the external file size, or 0 for a data: URI.
std::uint64_t checkUriMember(const Json& object, const std::string& what,
                             const AssetFolder& folder) {
  const Json& uriValue = object.at("uri");
  if (!uriValue.is_string()) throw Error(what + ": uri is not a string");
  const std::string uri = uriValue.get<std::string>();
  if (uri.starts_with("data:")) {
    if (!isSupportedDataUri(uri)) {
      throw Error(what + ": unsupported data: URI (must be base64 with a known MIME type)");
    }
    return 0;
  }
  try {
    return folder.checkUri(uri);
  } catch (const Error& e) {
    throw Error(what + ": " + e.what());
  }
}

}  // namespace

void precheckGltfJson(std::string_view text, bool isGlb, bool glbHasBin, const AssetFolder& folder,
                      std::uint64_t maxTotalBytes) {
  const Json root = parseBounded(text);
  if (!root.is_object()) throw Error("JSON root is not an object");

  std::uint64_t externalBytes = 0;
  auto addExternal = [&](std::uint64_t bytes, const std::string& what) {
    externalBytes = checkedAdd(externalBytes, bytes);
    if (externalBytes > maxTotalBytes) {
      throw Error(what + ": external files together exceed the limit of " +
                  std::to_string(maxTotalBytes) + " bytes");
    }
  };

  if (const Json* buffers = arrayMember(root, "buffers")) {
    for (std::size_t i = 0; i < buffers->size(); ++i) {
      const Json& buffer = (*buffers)[i];
      const std::string what = "buffer " + std::to_string(i);
      if (!buffer.is_object()) throw Error(what + " is not an object");
      const bool hasUri = buffer.contains("uri") &&
                          !(buffer["uri"].is_string() && buffer["uri"].get<std::string>().empty());
      if (!hasUri) {
        // Only the first buffer of a .glb refers to the BIN chunk; tinygltf would copy the chunk
        // once per uri-less buffer.
        if (!isGlb || i != 0) throw Error(what + " has no uri");
        if (!glbHasBin) throw Error(what + " refers to the GLB BIN chunk but the file has none");
        continue;
      }
      addExternal(checkUriMember(buffer, what, folder), what);
    }
  }

  if (const Json* images = arrayMember(root, "images")) {
    for (std::size_t i = 0; i < images->size(); ++i) {
      const Json& image = (*images)[i];
      const std::string what = "image " + std::to_string(i);
      if (!image.is_object()) throw Error(what + " is not an object");
      if (image.contains("uri")) addExternal(checkUriMember(image, what, folder), what);
    }
  }

  if (const Json* views = arrayMember(root, "bufferViews")) {
    for (std::size_t i = 0; i < views->size(); ++i) {
      const Json& view = (*views)[i];
      if (!view.is_object() || !view.contains("byteStride")) continue;
      const Json& stride = view["byteStride"];
      const bool valid = stride.is_number_unsigned() && stride.get<std::uint64_t>() >= 4 &&
                         stride.get<std::uint64_t>() <= 252 && stride.get<std::uint64_t>() % 4 == 0;
      if (!valid) {
        throw Error("bufferView " + std::to_string(i) + ": byteStride " + stride.dump() +
                    " is invalid (must be a multiple of 4 from 4 to 252)");
      }
    }
  }
}

}  // namespace engine::assets::gltf
