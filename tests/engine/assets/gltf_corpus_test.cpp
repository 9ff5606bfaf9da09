// Malformed and hostile glTF files, each generated from a valid template with one fault, each
// expected to fail with an engine::Error naming the file and the fault. The last tests mutate
// every integer field and truncate a .glb at every length: load or engine::Error, nothing else
// (run under AddressSanitizer/UBSan by engine_gltf_asan_tests).
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <limits>

#include "engine/assets/gltf_loader.h"
#include "engine/core/error.h"
#include "gltf_test_asset.h"

namespace {

namespace fs = std::filesystem;
using engine::assets::GltfLimits;
using engine::assets::loadGltfMesh;
using gltf_test::Json;
using gltf_test::TestAsset;

using Edit = std::function<void(TestAsset&)>;

// One malformed file: `make` writes it into the asset folder (whose parent holds secret.bin)
// and returns the path to load.
struct CorpusCase {
  std::string name;
  std::function<fs::path(const fs::path& folder)> make;
  std::string expected;  // distinctive part of the message
  GltfLimits limits{};
};

std::ostream& operator<<(std::ostream& out, const CorpusCase& c) {
  return out << c.name;
}

std::function<fs::path(const fs::path&)> gltf(Edit edit, bool withNormals = true) {
  return [=](const fs::path& folder) {
    TestAsset asset = gltf_test::quadAsset(withNormals);
    edit(asset);
    return asset.writeGltf(folder, "asset");
  };
}

std::function<fs::path(const fs::path&)> glb(Edit edit) {
  return [=](const fs::path& folder) {
    TestAsset asset = gltf_test::quadAsset();
    edit(asset);
    return asset.writeGlb(folder, "asset");
  };
}

// A .glb of the quad with its bytes edited after encoding.
std::function<fs::path(const fs::path&)> glbBytes(
    std::function<void(std::vector<std::uint8_t>&)> edit) {
  return [=](const fs::path& folder) {
    std::vector<std::uint8_t> bytes = gltf_test::quadAsset().glbBytes();
    edit(bytes);
    const fs::path path = folder / "asset.glb";
    gltf_test::writeBytes(path, bytes);
    return path;
  };
}

std::function<fs::path(const fs::path&)> rawFile(std::string name, std::string content) {
  return [=](const fs::path& folder) {
    gltf_test::writeBytes(folder / name, std::vector<std::uint8_t>(content.begin(), content.end()));
    return folder / name;
  };
}

void putU32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::uint32_t value) {
  std::memcpy(bytes.data() + offset, &value, 4);
}

std::uint32_t getU32(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, 4);
  return value;
}

void setPositionX(TestAsset& asset, std::size_t vertex, float value) {
  std::memcpy(asset.bin.data() + vertex * 12, &value, 4);  // positions are view 0 at offset 0
}

Json& primitive(TestAsset& asset) {
  return asset.json["meshes"][0]["primitives"][0];
}

std::vector<CorpusCase> corpus() {
  const std::uint64_t hundredMillion = 100'000'000;
  GltfLimits huge;
  huge.maxTotalVertices = std::numeric_limits<std::uint64_t>::max();
  huge.maxTotalIndices = std::numeric_limits<std::uint64_t>::max();
  GltfLimits tinyFile;
  tinyFile.maxFileBytes = 100;
  GltfLimits smallExternal;
  smallExternal.maxFileBytes = 64 * 1024;
  GltfLimits smallTotal;
  smallTotal.maxTotalExternalBytes = 300;
  GltfLimits sixVertices;
  sixVertices.maxTotalVertices = 6;
  GltfLimits smallTexture;
  smallTexture.maxFileBytes = 1 << 20;

  return {
      // --- Container
      {"EmptyGltf", rawFile("empty.gltf", ""), "file is empty"},
      {"EmptyGlb", rawFile("empty.glb", ""), "file is empty"},
      {"GlbHeaderOnly", glbBytes([](auto& b) {
         b.resize(12);
         putU32(b, 8, 12);
       }),
       "GLB truncated: no JSON chunk header"},
      {"GlbShorterThanItsHeaderSays", glbBytes([](auto& b) { b.resize(b.size() / 2); }),
       "does not match the file size"},
      {"GlbJsonChunkPastEnd", glbBytes([](auto& b) { putU32(b, 12, 0x7FFFFFF0u); }),
       "GLB chunk 0 length 2147483632 runs past the end of the file"},
      {"GlbBinChunkPastEnd",  // 8 bytes too long: the overrun tinygltf's own check misses
       glbBytes([](auto& b) {
         const std::size_t binHeader = 20 + getU32(b, 12);
         putU32(b, binHeader, getU32(b, binHeader) + 8);
       }),
       "GLB chunk 1 length"},
      {"GlbBadMagic", glbBytes([](auto& b) { b[3] = 'X'; }), "bad magic"},
      {"GlbVersion1", glbBytes([](auto& b) { putU32(b, 4, 1); }), "GLB version 1"},
      {"GlbBufferWithoutBinChunk",
       [](const fs::path& folder) {
         std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":4}]})";
         while (json.size() % 4 != 0) json += ' ';
         std::vector<std::uint8_t> bytes(20 + json.size());
         std::memcpy(bytes.data(), "glTF", 4);
         putU32(bytes, 4, 2);
         putU32(bytes, 8, static_cast<std::uint32_t>(bytes.size()));
         putU32(bytes, 12, static_cast<std::uint32_t>(json.size()));
         std::memcpy(bytes.data() + 16, "JSON", 4);
         std::memcpy(bytes.data() + 20, json.data(), json.size());
         gltf_test::writeBytes(folder / "nobin.glb", bytes);
         return folder / "nobin.glb";
       },
       "buffer 0 refers to the GLB BIN chunk but the file has none"},
      {"InvalidJson", rawFile("bad.gltf", "{ \"asset\": "), "JSON parse error"},
      {"DeepJsonNesting",
       rawFile("deep.gltf", R"({"asset":{"version":"2.0"},"extras":)" + std::string(1000, '[') +
                                std::string(1000, ']') + "}"),
       "JSON nesting deeper than 64 levels"},
      {"FileOverSizeLimit", gltf([](TestAsset&) {}), "over the limit of 100", tinyFile},

      // --- Accessors and views
      {"AccessorCountPastView", gltf([](TestAsset& a) { a.json["accessors"][0]["count"] = 5; }),
       "accessor 0 (POSITION): byteOffset 0 + 5 elements of stride 12 runs past the end of "
       "bufferView 0"},
      {"HugeCountOverVertexLimit", gltf([=](TestAsset& a) {
         a.json["bufferViews"][0]["byteLength"] = 12;
         a.json["accessors"][0]["count"] = hundredMillion;
       }),
       "accessor 0 (POSITION): count 100000000 is over the limit of 33554432"},
      {"HugeCountOnTwelveByteView", gltf([=](TestAsset& a) {
         a.json["bufferViews"][0]["byteLength"] = 12;
         a.json["accessors"][0]["count"] = hundredMillion;
       }),
       "100000000 elements of stride 12 runs past the end of bufferView 0 (12 bytes)", huge},
      {"CountTimesStrideOverflows",
       gltf([](TestAsset& a) { a.json["accessors"][0]["count"] = std::uint64_t{1} << 62; }),
       "runs past the end of bufferView 0", huge},
      {"AccessorByteOffsetPastView",
       gltf([](TestAsset& a) { a.json["accessors"][0]["byteOffset"] = 40; }),
       "byteOffset 40 + 4 elements"},
      {"StrideSmallerThanElement",
       gltf([](TestAsset& a) { a.json["bufferViews"][0]["byteStride"] = 8; }),
       "bufferView 0 byteStride 8 is smaller than the 12-byte element"},
      {"StrideNotMultipleOfFour",
       gltf([](TestAsset& a) { a.json["bufferViews"][0]["byteStride"] = 14; }),
       "bufferView 0: byteStride 14 is invalid"},
      {"StrideOver252", gltf([](TestAsset& a) { a.json["bufferViews"][0]["byteStride"] = 256; }),
       "bufferView 0: byteStride 256 is invalid"},
      {"BufferViewPastBuffer",
       gltf([](TestAsset& a) { a.json["bufferViews"][0]["byteOffset"] = 150; }),
       "bufferView 0 (byteOffset 150, byteLength 48) lies outside buffer 0"},
      {"BufferViewBufferOutOfRange",
       gltf([](TestAsset& a) { a.json["bufferViews"][0]["buffer"] = 7; }),
       "bufferView 0: buffer 7 is out of range"},
      {"AccessorBufferViewOutOfRange",
       gltf([](TestAsset& a) { a.json["accessors"][0]["bufferView"] = 42; }),
       "accessor 0 (POSITION): bufferView 42 is out of range"},
      {"AccessorWithoutBufferView",
       gltf([](TestAsset& a) { a.json["accessors"][0].erase("bufferView"); }),
       "accessor 0 (POSITION): has no bufferView"},
      {"AttributeAccessorOutOfRange",
       gltf([](TestAsset& a) { primitive(a)["attributes"]["POSITION"] = 99; }),
       "accessor 99 (POSITION): index out of range"},
      {"PositionWrongComponentType",
       gltf([](TestAsset& a) { a.json["accessors"][0]["componentType"] = 5123; }),
       "accessor 0 (POSITION): type 3 with componentType 5123 is not allowed"},
      {"IndicesAsFloat", gltf([](TestAsset& a) { a.json["accessors"][4]["componentType"] = 5126; }),
       "accessor 4 (indices): type 65 with componentType 5126 is not allowed"},
      {"SparseAccessor", gltf([](TestAsset& a) {
         a.json["accessors"][0]["sparse"] = {
             {"count", 1},
             {"indices", {{"bufferView", 4}, {"componentType", 5123}}},
             {"values", {{"bufferView", 0}}}};
       }),
       "accessor 0 (POSITION): sparse accessors are not supported"},
      {"NormalCountDiffers", gltf([](TestAsset& a) { a.json["accessors"][1]["count"] = 3; }),
       "accessor 1 (NORMAL): count 3 differs from POSITION's 4"},
      {"MissingPosition", gltf([](TestAsset& a) { primitive(a)["attributes"].erase("POSITION"); }),
       "mesh 0 primitive 0 (node 0) has no POSITION attribute"},
      {"IndexBeyondVertexCount", gltf([](TestAsset& a) {
         const std::uint16_t seven = 7;
         std::memcpy(a.bin.data() + a.json["bufferViews"][4]["byteOffset"].get<std::size_t>() + 4,
                     &seven, 2);
       }),
       "accessor 4 (indices): element 2: index 7 is >= the primitive's vertex count 4"},
      {"IndicesNotWholeTriangles", gltf([](TestAsset& a) { a.json["accessors"][4]["count"] = 4; }),
       "4 indices do not form whole triangles"},
      {"NanPosition", gltf([](TestAsset& a) { setPositionX(a, 1, std::nanf("")); }),
       "accessor 0 (POSITION): element 1 is not finite"},
      {"InfPosition",
       gltf([](TestAsset& a) { setPositionX(a, 3, std::numeric_limits<float>::infinity()); }),
       "accessor 0 (POSITION): element 3 is not finite"},
      {"NoTrianglePrimitives", gltf([](TestAsset& a) { primitive(a)["mode"] = 1; }),
       "no triangle primitives"},
      {"VertexTotalOverLimit", gltf([](TestAsset& a) {
         a.json["nodes"] = Json::array({{{"mesh", 0}}, {{"mesh", 0}}});
         a.json["scenes"][0]["nodes"] = {0, 1};
       }),
       "mesh 0 primitive 0 (node 1): 8 vertices in total, over the limit of 6", sixVertices},
      {"MaterialOutOfRange", gltf([](TestAsset& a) { primitive(a)["material"] = 4; }),
       "material 4 is out of range"},

      // --- External files and URIs
      {"MissingExternalBuffer",
       gltf([](TestAsset& a) { a.json["buffers"][0]["uri"] = "missing.bin"; }),
       "buffer 0: uri 'missing.bin': external file"},
      {"DotDotUri", gltf([](TestAsset& a) { a.json["buffers"][0]["uri"] = "../secret.bin"; }),
       "buffer 0: uri '../secret.bin': '..' segments are not allowed"},
      {"PercentEncodedDotDotUri",
       gltf([](TestAsset& a) { a.json["buffers"][0]["uri"] = "sub/%2e%2e/%2E%2E/secret.bin"; }),
       "'..' segments are not allowed"},
      {"AbsolutePathUri",
       [](const fs::path& folder) {
         TestAsset asset = gltf_test::quadAsset();
         asset.json["buffers"][0]["uri"] = (folder.parent_path() / "secret.bin").string();
         return asset.writeGltf(folder, "asset");
       },
       "absolute paths are not allowed"},
      {"HttpUri",
       gltf([](TestAsset& a) { a.json["buffers"][0]["uri"] = "http://example.com/quad.bin"; }),
       "scheme 'http:' is not allowed"},
      {"FileUri", gltf([](TestAsset& a) { a.json["buffers"][0]["uri"] = "file:///etc/passwd"; }),
       "scheme 'file:' is not allowed"},
      {"SymlinkLeavingFolder",
       [](const fs::path& folder) {
         fs::create_symlink(folder.parent_path() / "secret.bin", folder / "link.bin");
         TestAsset asset = gltf_test::quadAsset();
         asset.json["buffers"][0]["uri"] = "link.bin";
         return asset.writeGltf(folder, "asset");
       },
       "uri 'link.bin': resolves outside the asset folder"},
      {"UnsupportedDataUri",
       gltf([](TestAsset& a) { a.json["buffers"][0]["uri"] = "data:text/html,<b>hi</b>"; }),
       "buffer 0: unsupported data: URI"},
      {"GltfBufferWithoutUri", gltf([](TestAsset& a) { a.json["buffers"][0]["uri"] = ""; }),
       "buffer 0 has no uri"},
      {"ExternalBufferOverSizeLimit", gltf([](TestAsset& a) {
         a.bin.resize(100 * 1024);
         a.json["buffers"][0]["byteLength"] = a.bin.size();
       }),
       "buffer 0: uri 'asset.bin': file is 102400 bytes, over the limit of 65536", smallExternal},
      {"ExternalFilesOverTotalLimit", gltf([](TestAsset& a) {
         a.json["buffers"][1] = {{"uri", "asset.bin"}, {"byteLength", 156}};
       }),
       "buffer 1: external files together exceed the limit of 300 bytes", smallTotal},
      {"ImageUriLeavesFolder", gltf([](TestAsset& a) {
         a.json["images"] = Json::array({{{"uri", "../secret.png"}}});
       }),
       "image 0: uri '../secret.png': '..' segments"},

      // --- Nodes and scenes
      {"NodeCycle", gltf([](TestAsset& a) {
         a.json["nodes"] = Json::array({{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}});
         a.json["scenes"][0]["nodes"] = Json::array();
       }),
       "node 0 is in a cycle of the node hierarchy"},
      {"NodeIsItsOwnChild", gltf([](TestAsset& a) { a.json["nodes"][0]["children"] = {0}; }),
       "node 0 is its own child"},
      {"NodeWithTwoParents", gltf([](TestAsset& a) {
         a.json["nodes"] = Json::array({{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}});
         a.json["scenes"][0]["nodes"] = {0, 1};
       }),
       "node 2 has more than one parent (node 0 and node 1)"},
      {"NodeChildOutOfRange", gltf([](TestAsset& a) { a.json["nodes"][0]["children"] = {9}; }),
       "node 0: child 9 is out of range (1 nodes)"},
      {"MeshIndexOutOfRange", gltf([](TestAsset& a) { a.json["nodes"][0]["mesh"] = 5; }),
       "node 0: mesh 5 is out of range (1 meshes)"},
      {"SceneOutOfRange", gltf([](TestAsset& a) { a.json["scene"] = 3; }),
       "scene 3 is out of range (1 scenes)"},
      {"SceneNodeOutOfRange", gltf([](TestAsset& a) { a.json["scenes"][0]["nodes"] = {4}; }),
       "scene 0: node 4 is out of range"},
      {"SceneListsRootTwice", gltf([](TestAsset& a) {
         a.json["scenes"][0]["nodes"] = {0, 0};
       }),
       "scene 0 lists node 0 twice"},
      {"MatrixWrongSize", gltf([](TestAsset& a) {
         a.json["nodes"][0]["matrix"] = {1, 0, 0};
       }),
       "node 0: matrix has 3 values, expected 16"},
      {"ZeroRotation", gltf([](TestAsset& a) {
         a.json["nodes"][0]["rotation"] = {0, 0, 0, 0};
       }),
       "node 0: rotation is a zero quaternion"},

      // --- Images
      {"ImageBufferViewPastBuffer",  // must fail before any decoder sees the bytes
       glb([](TestAsset& a) {
         gltf_test::addBaseColorPng(a, gltf_test::encodePng(1, 1, {1, 2, 3, 4}));
         a.json["bufferViews"].back()["byteOffset"] = 100000;
       }),
       "image 0: bufferView 5 (byteOffset 100000, byteLength "},
      {"UnusedImageBufferViewPastBuffer", glb([](TestAsset& a) {
         gltf_test::addBaseColorPng(a, gltf_test::encodePng(1, 1, {1, 2, 3, 4}));
         a.json["materials"][0]["pbrMetallicRoughness"].erase("baseColorTexture");
         a.json["bufferViews"].back()["byteLength"] = 1u << 30;
       }),
       "image 0: bufferView 5 (byteOffset 156, byteLength 1073741824) lies outside buffer 0"},
      {"CorruptPng", glb([](TestAsset& a) {
         gltf_test::addBaseColorPng(a, std::vector<std::uint8_t>(64, 0xAB));
       }),
       "image 0: cannot decode image"},
      {"TextureOverDecodedLimit",  // a 1x1 PNG whose header claims 4096x4096
       glb([](TestAsset& a) {
         std::vector<std::uint8_t> png = gltf_test::encodePng(1, 1, {1, 2, 3, 4});
         const std::uint8_t size4096[4] = {0, 0, 0x10, 0};  // big-endian 4096
         std::memcpy(png.data() + 16, size4096, 4);         // IHDR width
         std::memcpy(png.data() + 20, size4096, 4);         // IHDR height
         gltf_test::addBaseColorPng(a, png);
       }),
       "image 0: image is 4096x4096, over the decoded size limit of 1048576 bytes", smallTexture},
      {"TextureIndexOutOfRange", glb([](TestAsset& a) {
         a.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 3}};
       }),
       "material 0: baseColorTexture 3 is out of range (0 textures)"},
  };
}

class GltfCorpusTest : public ::testing::TestWithParam<CorpusCase> {
 protected:
  void SetUp() override {
    folder_ = dir_.path() / "asset";
    fs::create_directories(folder_);
    const std::string secret = "SECRET";
    gltf_test::writeBytes(dir_.path() / "secret.bin",
                          std::vector<std::uint8_t>(secret.begin(), secret.end()));
  }

  gltf_test::TempDir dir_;
  fs::path folder_;
};

TEST_P(GltfCorpusTest, FailsWithAnErrorNamingFileAndFault) {
  const CorpusCase& c = GetParam();
  const fs::path file = c.make(folder_);
  try {
    (void)loadGltfMesh(file, c.limits);
    ADD_FAILURE() << file << " loaded; expected an error containing: " << c.expected;
  } catch (const engine::Error& e) {
    const std::string message = e.what();
    RecordProperty("message", message);  // in --gtest_output=xml reports, for review
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "expected: " << c.expected << "\nactual:   " << message;
  }
}

INSTANTIATE_TEST_SUITE_P(Malformed, GltfCorpusTest, ::testing::ValuesIn(corpus()),
                         [](const auto& testInfo) { return testInfo.param.name; });

// Loads or throws engine::Error; any other exception (or a sanitizer report) fails.
void expectLoadOrError(const fs::path& file, const std::string& what) {
  try {
    (void)loadGltfMesh(file);
  } catch (const engine::Error&) {
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": threw a non-engine::Error: " << e.what();
  }
}

// Every integer in the JSON (indices, offsets, lengths, counts, strides, types) replaced in
// turn by each of a set of edge values.
TEST(GltfCorpusMutation, EveryIntegerFieldTakesEdgeValues) {
  gltf_test::TempDir dir;
  TestAsset base = gltf_test::quadAsset();
  gltf_test::addBaseColorPng(base, gltf_test::encodePng(2, 1, {1, 2, 3, 4, 5, 6, 7, 8}));
  base.json["buffers"][0]["byteLength"] = base.bin.size();
  const Json flat = base.json.flatten();
  const std::vector<std::int64_t> values = {
      -1,  0,   1,   2,   3,   4,     5,          12,           13,
      155, 156, 157, 252, 256, 65535, 2147483647, 4294967295LL, std::int64_t{1} << 53};
  int loads = 0;
  for (const auto& [pointer, value] : flat.items()) {
    if (!value.is_number_integer()) continue;
    for (const std::int64_t v : values) {
      TestAsset mutated = base;
      mutated.json[Json::json_pointer(pointer)] = v;
      expectLoadOrError(mutated.writeGlb(dir.path(), "mutated"),
                        pointer + " = " + std::to_string(v));
      ++loads;
    }
  }
  EXPECT_GT(loads, 300);
}

TEST(GltfCorpusMutation, TruncatedAndBitFlippedGlb) {
  gltf_test::TempDir dir;
  TestAsset asset = gltf_test::quadAsset();
  gltf_test::addBaseColorPng(asset, gltf_test::encodePng(2, 1, {1, 2, 3, 4, 5, 6, 7, 8}));
  const std::vector<std::uint8_t> bytes = asset.glbBytes();
  const fs::path file = dir.path() / "mutated.glb";
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    gltf_test::writeBytes(
        file, std::vector<std::uint8_t>(bytes.begin(),
                                        bytes.begin() + static_cast<std::ptrdiff_t>(length)));
    expectLoadOrError(file, "truncated to " + std::to_string(length));
  }
  std::uint32_t state = 12345;  // deterministic LCG: the same mutations every run
  auto next = [&state] { return state = state * 1664525u + 1013904223u; };
  for (int i = 0; i < 2000; ++i) {
    std::vector<std::uint8_t> mutated = bytes;
    for (int flips = 0; flips < 1 + i % 4; ++flips) {
      mutated[next() % mutated.size()] = static_cast<std::uint8_t>(next() >> 24);
    }
    gltf_test::writeBytes(file, mutated);
    expectLoadOrError(file, "mutation " + std::to_string(i));
  }
}

}  // namespace
