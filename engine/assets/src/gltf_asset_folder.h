#pragma once
// The only place a glTF file may load external buffers and images from: its own folder and the
// folders below it. Serves as tinygltf's file system so that nothing else is reachable.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace engine::assets::gltf {

// True for the base64 data: URIs tinygltf decodes itself (the MIME types it knows).
bool isSupportedDataUri(const std::string& uri);

// Percent-decodes a URI exactly as tinygltf 2.7.0 does before opening it ('+' becomes a space),
// so that the path checked is the path opened.
std::string decodeUriLikeTinyGltf(const std::string& uri);

class AssetFolder {
 public:
  // `assetFile` is the .gltf/.glb; its canonical parent folder becomes the root.
  AssetFolder(const std::filesystem::path& assetFile, std::uint64_t maxFileBytes,
              std::uint64_t maxTotalBytes);

  // The canonical root folder, absolute.
  const std::filesystem::path& root() const { return root_; }

  // Resolves a non-data URI to an existing regular file inside the root that is within the
  // per-file size limit. Throws engine::Error ("uri '<uri>' ...") for a URI scheme, an absolute
  // path, a '..' segment, control characters, a path that leaves the root (symlinks included),
  // a missing file or one over the limit. Returns the file's size.
  std::uint64_t checkUri(const std::string& uri) const;

  // File system callbacks for tinygltf: reads only confined files, each within the per-file
  // limit and all together within the total; never writes. Valid while this object lives.
  tinygltf::FsCallbacks callbacks();

 private:
  bool contains(const std::filesystem::path& path) const;
  bool readConfined(const std::string& path, std::vector<unsigned char>& out, std::string& err);

  static bool fileExists(const std::string& path, void* self);
  static std::string expandPath(const std::string& path, void* self);
  static bool readWholeFile(std::vector<unsigned char>* out, std::string* err,
                            const std::string& path, void* self);
  static bool writeWholeFile(std::string* err, const std::string& path,
                             const std::vector<unsigned char>& contents, void* self);

  std::filesystem::path root_;
  std::uint64_t maxFileBytes_;
  std::uint64_t maxTotalBytes_;
  std::uint64_t bytesRead_ = 0;
};

}  // namespace engine::assets::gltf
