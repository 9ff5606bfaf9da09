#pragma once
// Builds glTF test assets in code: a JSON document plus the bytes of its one binary buffer,
// edited by a test and then written as .gltf + .bin, .glb, or .gltf with a data: URI.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace gltf_test {

using Json = nlohmann::json;

constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

struct TestAsset {
  Json json;
  std::vector<std::uint8_t> bin;  // buffer 0

  // Appends `bytes` to buffer 0 (4-byte aligned) as a new bufferView; returns its index.
  int addView(const void* data, std::size_t bytes, int byteStride = 0);
  // Adds an accessor on `view`; returns its index.
  int addAccessor(int view, int componentType, std::size_t count, const std::string& type,
                  bool normalized = false);

  // Buffer 0 gets byteLength = bin.size() and, where the test set none, uri "<name>.bin".
  // Writes <dir>/<name>.gltf and <dir>/<name>.bin; returns the .gltf path.
  std::filesystem::path writeGltf(const std::filesystem::path& dir, const std::string& name) const;
  // Buffer 0 (without uri unless the test set one) is the BIN chunk.
  std::filesystem::path writeGlb(const std::filesystem::path& dir, const std::string& name) const;
  // Buffer 0 as a base64 data: URI.
  std::filesystem::path writeEmbedded(const std::filesystem::path& dir,
                                      const std::string& name) const;
  // The .glb file's bytes (what writeGlb writes).
  std::vector<std::uint8_t> glbBytes() const;
};

// A unit quad in the XY plane, counter-clockwise seen from +Z: positions (0,0,0) (1,0,0)
// (1,1,0) (0,1,0) (accessor 0, view 0), normals +Z (accessor 1), uvs equal to x,y
// (accessor 2), UNSIGNED_BYTE normalised colours kQuadColors (accessor 3), UNSIGNED_SHORT
// indices 0 1 2 0 2 3 (accessor 4); material 0 with baseColorFactor (0.5, 1, 1, 1); one node
// drawing mesh 0 in scene 0.
TestAsset quadAsset(bool withNormals = true);
inline const std::uint8_t kQuadColors[4][4] = {
    {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 51}};

// A mesh of FLOAT positions only and, unless `indices` is empty, UNSIGNED_INT indices
// (accessor 1); one node, one scene, no material.
TestAsset positionsAsset(const std::vector<glm::vec3>& positions,
                         const std::vector<std::uint32_t>& indices);

// Makes material 0 use a base colour texture whose image is `png` in a new bufferView.
void addBaseColorPng(TestAsset& asset, const std::vector<std::uint8_t>& png);

// An RGBA8 PNG (stored deflate, no compression).
std::vector<std::uint8_t> encodePng(std::uint32_t width, std::uint32_t height,
                                    const std::vector<std::uint8_t>& rgba);
std::string base64(const std::vector<std::uint8_t>& bytes);
void writeBytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

// A fresh folder under the system temp folder, removed with everything in it on destruction.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace gltf_test
