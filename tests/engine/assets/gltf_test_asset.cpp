#include "gltf_test_asset.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace gltf_test {
namespace fs = std::filesystem;
namespace {

void appendU32(std::vector<std::uint8_t>& out, std::uint32_t v) {  // little-endian
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

void appendU32Be(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 3; i >= 0; --i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

void appendPngChunk(std::vector<std::uint8_t>& png, const char* type,
                    const std::vector<std::uint8_t>& data) {
  appendU32Be(png, static_cast<std::uint32_t>(data.size()));
  const std::size_t typeStart = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  appendU32Be(png, crc32(png.data() + typeStart, png.size() - typeStart));
}

Json withBuffer(const TestAsset& asset, const std::string* uri) {
  Json json = asset.json;
  Json& buffer = json["buffers"][0];
  if (!buffer.contains("byteLength")) buffer["byteLength"] = asset.bin.size();
  if (uri && !buffer.contains("uri")) buffer["uri"] = *uri;
  return json;
}

template <typename T>
int addArray(TestAsset& asset, const std::vector<T>& values, int componentType,
             const std::string& type, bool normalized = false) {
  const int view = asset.addView(values.data(), values.size() * sizeof(T));
  return asset.addAccessor(view, componentType, values.size(), type, normalized);
}

Json singleNodeScene() {
  return Json{{"nodes", Json::array({Json{{"mesh", 0}}})},
              {"scenes", Json::array({Json{{"nodes", Json::array({0})}}})},
              {"scene", 0}};
}

}  // namespace

int TestAsset::addView(const void* data, std::size_t bytes, int byteStride) {
  while (bin.size() % 4 != 0) bin.push_back(0);
  Json view{{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
  if (byteStride != 0) view["byteStride"] = byteStride;
  const auto* first = static_cast<const std::uint8_t*>(data);
  bin.insert(bin.end(), first, first + bytes);
  json["bufferViews"].push_back(view);
  return static_cast<int>(json["bufferViews"].size()) - 1;
}

int TestAsset::addAccessor(int view, int componentType, std::size_t count, const std::string& type,
                           bool normalized) {
  // byteOffset spelled out (though 0 is the default) so that mutation tests find and vary it.
  Json accessor{{"bufferView", view},
                {"byteOffset", 0},
                {"componentType", componentType},
                {"count", count},
                {"type", type}};
  if (normalized) accessor["normalized"] = true;
  json["accessors"].push_back(accessor);
  return static_cast<int>(json["accessors"].size()) - 1;
}

fs::path TestAsset::writeGltf(const fs::path& dir, const std::string& name) const {
  const std::string binName = name + ".bin";
  writeBytes(dir / binName, bin);
  const fs::path path = dir / (name + ".gltf");
  std::ofstream(path) << withBuffer(*this, &binName).dump(1);
  return path;
}

std::vector<std::uint8_t> TestAsset::glbBytes() const {
  std::string text = withBuffer(*this, nullptr).dump();
  while (text.size() % 4 != 0) text += ' ';
  std::vector<std::uint8_t> chunk = bin;
  while (chunk.size() % 4 != 0) chunk.push_back(0);
  std::vector<std::uint8_t> out;
  out.insert(out.end(), {'g', 'l', 'T', 'F'});
  appendU32(out, 2);
  appendU32(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + chunk.size()));
  appendU32(out, static_cast<std::uint32_t>(text.size()));
  appendU32(out, 0x4E4F534Au);
  out.insert(out.end(), text.begin(), text.end());
  appendU32(out, static_cast<std::uint32_t>(chunk.size()));
  appendU32(out, 0x004E4942u);
  out.insert(out.end(), chunk.begin(), chunk.end());
  return out;
}

fs::path TestAsset::writeGlb(const fs::path& dir, const std::string& name) const {
  const fs::path path = dir / (name + ".glb");
  writeBytes(path, glbBytes());
  return path;
}

fs::path TestAsset::writeEmbedded(const fs::path& dir, const std::string& name) const {
  const std::string uri = "data:application/octet-stream;base64," + base64(bin);
  const fs::path path = dir / (name + ".gltf");
  std::ofstream(path) << withBuffer(*this, &uri).dump(1);
  return path;
}

TestAsset quadAsset(bool withNormals) {
  TestAsset asset;
  asset.json = singleNodeScene();
  asset.json["asset"] = {{"version", "2.0"}};
  asset.json["buffers"] = Json::array({Json::object()});
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<glm::vec3> normals(4, glm::vec3(0, 0, 1));
  const std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<std::uint8_t> colors(&kQuadColors[0][0], &kQuadColors[0][0] + 16);
  const std::vector<std::uint16_t> indices = {0, 1, 2, 0, 2, 3};

  Json attributes;
  attributes["POSITION"] = addArray(asset, positions, kFloat, "VEC3");
  const int normalAccessor = addArray(asset, normals, kFloat, "VEC3");
  if (withNormals) attributes["NORMAL"] = normalAccessor;
  attributes["TEXCOORD_0"] = addArray(asset, uvs, kFloat, "VEC2");
  const int colorView = asset.addView(colors.data(), colors.size());
  attributes["COLOR_0"] = asset.addAccessor(colorView, kUnsignedByte, 4, "VEC4", true);
  const int indexAccessor = addArray(asset, indices, kUnsignedShort, "SCALAR");
  asset.json["meshes"] = Json::array(
      {Json{{"primitives",
             Json::array({Json{
                 {"attributes", attributes}, {"indices", indexAccessor}, {"material", 0}}})}}});
  asset.json["materials"] =
      Json::array({Json{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 1.0, 1.0, 1.0}}}}}});
  return asset;
}

TestAsset positionsAsset(const std::vector<glm::vec3>& positions,
                         const std::vector<std::uint32_t>& indices) {
  TestAsset asset;
  asset.json = singleNodeScene();
  asset.json["asset"] = {{"version", "2.0"}};
  asset.json["buffers"] = Json::array({Json::object()});
  Json primitive{{"attributes", {{"POSITION", addArray(asset, positions, kFloat, "VEC3")}}}};
  if (!indices.empty()) primitive["indices"] = addArray(asset, indices, kUnsignedInt, "SCALAR");
  asset.json["meshes"] = Json::array({Json{{"primitives", Json::array({primitive})}}});
  return asset;
}

void addBaseColorPng(TestAsset& asset, const std::vector<std::uint8_t>& png) {
  const int view = asset.addView(png.data(), png.size());
  asset.json["images"] = Json::array({Json{{"bufferView", view}, {"mimeType", "image/png"}}});
  asset.json["textures"] = Json::array({Json{{"source", 0}}});
  asset.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
}

std::vector<std::uint8_t> encodePng(std::uint32_t width, std::uint32_t height,
                                    const std::vector<std::uint8_t>& rgba) {
  if (rgba.size() != std::size_t{4} * width * height) throw std::invalid_argument("pixel count");
  std::vector<std::uint8_t> raw;  // each row: filter type 0, then the pixels
  for (std::uint32_t y = 0; y < height; ++y) {
    raw.push_back(0);
    const auto row = rgba.begin() + static_cast<std::ptrdiff_t>(std::size_t{4} * width * y);
    raw.insert(raw.end(), row, row + static_cast<std::ptrdiff_t>(4 * width));
  }
  if (raw.size() > 65535) throw std::invalid_argument("one stored block holds 65535 bytes");
  std::vector<std::uint8_t> zlib = {0x78, 0x01, 0x01};  // header; final stored block
  const auto length = static_cast<std::uint16_t>(raw.size());
  const auto inverted = static_cast<std::uint16_t>(~length);
  zlib.insert(zlib.end(),
              {static_cast<std::uint8_t>(length), static_cast<std::uint8_t>(length >> 8),
               static_cast<std::uint8_t>(inverted), static_cast<std::uint8_t>(inverted >> 8)});
  zlib.insert(zlib.end(), raw.begin(), raw.end());
  std::uint32_t a = 1, b = 0;  // Adler-32
  for (const std::uint8_t byte : raw) {
    a = (a + byte) % 65521;
    b = (b + a) % 65521;
  }
  appendU32Be(zlib, (b << 16) | a);

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<std::uint8_t> header;
  appendU32Be(header, width);
  appendU32Be(header, height);
  header.insert(header.end(), {8, 6, 0, 0, 0});  // 8-bit RGBA, no interlace
  appendPngChunk(png, "IHDR", header);
  appendPngChunk(png, "IDAT", zlib);
  appendPngChunk(png, "IEND", {});
  return png;
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t group = std::uint32_t{bytes[i]} << 16;
    if (i + 1 < bytes.size()) group |= std::uint32_t{bytes[i + 1]} << 8;
    if (i + 2 < bytes.size()) group |= bytes[i + 2];
    out += table[(group >> 18) & 63];
    out += table[(group >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(group >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[group & 63] : '=';
  }
  return out;
}

void writeBytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = fs::temp_directory_path() /
          ("cloudscape_gltf_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  fs::remove_all(path_);
  fs::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

}  // namespace gltf_test
