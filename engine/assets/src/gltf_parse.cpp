#include "gltf_parse.h"

#include <exception>
#include <string>

#include "engine/core/error.h"

namespace engine::assets::gltf {
namespace {

// Installed instead of tinygltf's stb decoder. For a bufferView image tinygltf passes a pointer
// computed from an unchecked offset, so those bytes must not be touched here; the texture is
// decoded later from a validated range. URI images arrive as file bytes tinygltf owns: keep them.
bool keepImageBytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void*) {
  if (image->bufferView >= 0) return true;
  if (bytes != nullptr && size > 0) {
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
  }
  return true;
}

// tinygltf quotes whole data: URIs in some errors; keep messages readable.
std::string trimmed(std::string text) {
  constexpr std::size_t kMaxLength = 500;
  if (text.size() > kMaxLength) text = text.substr(0, kMaxLength) + "...";
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "unknown error" : text;
}

}  // namespace

tinygltf::Model parseGltf(std::span<const std::uint8_t> bytes, const GlbLayout* glb,
                          AssetFolder& folder) {
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(folder.callbacks());
  loader.SetImageLoader(&keepImageBytes, nullptr);

  tinygltf::Model model;
  std::string err;
  std::string warn;
  bool ok = false;
  // Sizes were capped at 4 GiB - 1 by the caller, so the unsigned int lengths below are exact.
  try {
    const std::string baseDir = folder.root().string();
    if (glb) {
      ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                       static_cast<unsigned int>(bytes.size()), baseDir);
    } else {
      ok = loader.LoadASCIIFromString(&model, &err, &warn,
                                      reinterpret_cast<const char*>(bytes.data()),
                                      static_cast<unsigned int>(bytes.size()), baseDir);
    }
  } catch (const std::exception& e) {
    // tinygltf throws on some malformed input (std::out_of_range for a zero-length GLB buffer).
    throw Error("glTF parse failed: " + trimmed(e.what()));
  }
  if (!ok) throw Error("glTF parse failed: " + trimmed(err));
  return model;
}

}  // namespace engine::assets::gltf
