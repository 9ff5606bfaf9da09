// Valid glTF files, built in code and written as .gltf + .bin, .glb and data: URI variants:
// attribute decoding, computed normals, node transforms, scene selection, the texture.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "engine/assets/gltf_loader.h"
#include "gltf_test_asset.h"

namespace {

using engine::assets::loadGltfMesh;
using engine::assets::MeshData;
using gltf_test::Json;

constexpr float kEps = 1e-5f;

void expectVec(const glm::vec3& actual, const glm::vec3& expected, const char* what) {
  EXPECT_NEAR(actual.x, expected.x, kEps) << what;
  EXPECT_NEAR(actual.y, expected.y, kEps) << what;
  EXPECT_NEAR(actual.z, expected.z, kEps) << what;
}

void expectSameMesh(const MeshData& a, const MeshData& b) {
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.uvs, b.uvs);
  EXPECT_EQ(a.colors, b.colors);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.boundsMin, b.boundsMin);
  EXPECT_EQ(a.boundsMax, b.boundsMax);
}

class GltfLoaderTest : public ::testing::Test {
 protected:
  gltf_test::TempDir dir_;
};

TEST_F(GltfLoaderTest, LoadsGltfWithExternalBin) {
  const MeshData mesh = loadGltfMesh(gltf_test::quadAsset().writeGltf(dir_.path(), "quad"));

  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_EQ(mesh.positions, positions);
  EXPECT_EQ(mesh.normals, std::vector<glm::vec3>(4, glm::vec3(0, 0, 1)));
  const std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(mesh.uvs, uvs);
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  ASSERT_EQ(mesh.colors.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    // UNSIGNED_BYTE normalised colour times baseColorFactor (0.5, 1, 1, 1).
    const glm::vec4 expected =
        glm::vec4(gltf_test::kQuadColors[i][0], gltf_test::kQuadColors[i][1],
                  gltf_test::kQuadColors[i][2], gltf_test::kQuadColors[i][3]) /
        255.0f * glm::vec4(0.5f, 1.0f, 1.0f, 1.0f);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(mesh.colors[i][c], expected[c], kEps) << i << "," << c;
  }
  EXPECT_EQ(mesh.boundsMin, glm::vec3(0, 0, 0));
  EXPECT_EQ(mesh.boundsMax, glm::vec3(1, 1, 0));
  EXPECT_EQ(mesh.baseColorTexture.width, 0u);
  EXPECT_TRUE(mesh.baseColorTexture.pixels.empty());
}

TEST_F(GltfLoaderTest, GlbAndDataUriGiveTheSameMesh) {
  const gltf_test::TestAsset asset = gltf_test::quadAsset();
  const MeshData reference = loadGltfMesh(asset.writeGltf(dir_.path(), "quad"));
  expectSameMesh(loadGltfMesh(asset.writeGlb(dir_.path(), "quad")), reference);
  expectSameMesh(loadGltfMesh(asset.writeEmbedded(dir_.path(), "embedded")), reference);
}

TEST_F(GltfLoaderTest, ComputesAreaWeightedNormalsWhenAbsent) {
  // Vertex 0 is shared by a triangle facing +Z with area 2 and one facing +X with area 0.5.
  const gltf_test::TestAsset asset = gltf_test::positionsAsset(
      {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 1, 2, 0, 3, 4});
  const MeshData mesh = loadGltfMesh(asset.writeGltf(dir_.path(), "shared"));
  ASSERT_EQ(mesh.normals.size(), 5u);
  // Face vectors are twice the area: (0,0,4) and (1,0,0). An unweighted mean would give (1,0,1).
  expectVec(mesh.normals[0], glm::normalize(glm::vec3(1, 0, 4)), "shared vertex");
  expectVec(mesh.normals[1], {0, 0, 1}, "vertex 1");
  expectVec(mesh.normals[3], {1, 0, 0}, "vertex 3");
  // No COLOR_0 and no material: white; no TEXCOORD_0: zeros.
  EXPECT_EQ(mesh.colors, std::vector<glm::vec4>(5, glm::vec4(1.0f)));
  EXPECT_EQ(mesh.uvs, std::vector<glm::vec2>(5, glm::vec2(0.0f)));
}

TEST_F(GltfLoaderTest, ComputedNormalsOfTheQuadFaceForward) {
  const MeshData mesh = loadGltfMesh(gltf_test::quadAsset(false).writeGlb(dir_.path(), "quad"));
  for (const glm::vec3& n : mesh.normals) expectVec(n, {0, 0, 1}, "quad normal");
}

TEST_F(GltfLoaderTest, AppliesNodeHierarchyTransforms) {
  // Parent translates by (10, 0, 0); child rotates 90 degrees about +Y and scales by 2.
  gltf_test::TestAsset asset = gltf_test::quadAsset();
  const float s = std::sqrt(0.5f);
  asset.json["nodes"] =
      Json::array({Json{{"translation", {10, 0, 0}}, {"children", {1}}},
                   Json{{"mesh", 0}, {"rotation", {0, s, 0, s}}, {"scale", {2, 2, 2}}}});
  const MeshData mesh = loadGltfMesh(asset.writeGltf(dir_.path(), "nodes"));
  // R_y(90) maps (x, y, z) to (z, y, -x).
  expectVec(mesh.positions[0], {10, 0, 0}, "p0");
  expectVec(mesh.positions[1], {10, 0, -2}, "p1");
  expectVec(mesh.positions[2], {10, 2, -2}, "p2");
  for (const glm::vec3& n : mesh.normals) expectVec(n, {1, 0, 0}, "rotated normal");
  expectVec(mesh.boundsMin, {10, 0, -2}, "boundsMin");
  expectVec(mesh.boundsMax, {10, 2, 0}, "boundsMax");

  // The same transform as one matrix gives the same mesh.
  const glm::mat4 matrix = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)) *
                           glm::mat4_cast(glm::quat(s, 0, s, 0)) *
                           glm::scale(glm::mat4(1.0f), glm::vec3(2));
  const float* m = glm::value_ptr(matrix);
  asset.json["nodes"] = Json::array({Json{{"mesh", 0}, {"matrix", std::vector<float>(m, m + 16)}}});
  const MeshData fromMatrix = loadGltfMesh(asset.writeGltf(dir_.path(), "matrix"));
  for (std::size_t i = 0; i < 4; ++i) {
    expectVec(fromMatrix.positions[i], mesh.positions[i], "matrix position");
    expectVec(fromMatrix.normals[i], mesh.normals[i], "matrix normal");
  }
}

TEST_F(GltfLoaderTest, NonUniformScaleTransformsNormalsByInverseTranspose) {
  gltf_test::TestAsset asset = gltf_test::quadAsset();
  const std::vector<glm::vec3> slanted(4, glm::normalize(glm::vec3(1, 1, 0)));
  const int view = asset.addView(slanted.data(), sizeof(glm::vec3) * 4);
  asset.json["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
      asset.addAccessor(view, gltf_test::kFloat, 4, "VEC3");
  asset.json["nodes"][0]["scale"] = {2, 1, 1};
  const MeshData mesh = loadGltfMesh(asset.writeGltf(dir_.path(), "scaled"));
  // Stretching x by 2 halves a normal's x: (1, 1, 0) -> (0.5, 1, 0). Transforming by the
  // matrix itself would give (2, 1, 0).
  for (const glm::vec3& n : mesh.normals) expectVec(n, glm::normalize(glm::vec3(0.5f, 1, 0)), "n");
}

TEST_F(GltfLoaderTest, MirroringTransformKeepsWindingAndNormalsConsistent) {
  for (const bool withNormals : {true, false}) {
    gltf_test::TestAsset asset = gltf_test::quadAsset(withNormals);
    asset.json["nodes"][0]["scale"] = {-1, 1, 1};
    const MeshData mesh = loadGltfMesh(asset.writeGltf(dir_.path(), "mirror"));
    expectVec(mesh.positions[1], {-1, 0, 0}, "mirrored x");
    // Mirrored in x, the quad's triangles turn clockwise seen from +Z; the loader swaps two
    // corners so that they stay counter-clockwise around the (still +Z) face normal.
    EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2}));
    for (const glm::vec3& n : mesh.normals) expectVec(n, {0, 0, 1}, "mirrored normal");
  }
}

TEST_F(GltfLoaderTest, UsesDefaultSceneOrEveryRootNode) {
  gltf_test::TestAsset asset = gltf_test::quadAsset();
  asset.json["nodes"] =
      Json::array({Json{{"mesh", 0}}, Json{{"mesh", 0}, {"translation", {0, 0, 5}}}});
  asset.json["scenes"] = Json::array({Json{{"nodes", {0}}}, Json{{"nodes", {1}}}});
  asset.json["scene"] = 1;
  const MeshData scene1 = loadGltfMesh(asset.writeGltf(dir_.path(), "scene1"));
  ASSERT_EQ(scene1.positions.size(), 4u);
  EXPECT_EQ(scene1.positions[0], glm::vec3(0, 0, 5));

  asset.json.erase("scene");  // no default: scene 0
  const MeshData scene0 = loadGltfMesh(asset.writeGltf(dir_.path(), "scene0"));
  ASSERT_EQ(scene0.positions.size(), 4u);
  EXPECT_EQ(scene0.positions[0], glm::vec3(0, 0, 0));

  asset.json.erase("scenes");  // no scenes at all: every root node, so the mesh twice
  const MeshData roots = loadGltfMesh(asset.writeGltf(dir_.path(), "roots"));
  ASSERT_EQ(roots.positions.size(), 8u);
  EXPECT_EQ(roots.positions[4], glm::vec3(0, 0, 5));
  EXPECT_EQ(roots.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7}));
}

TEST_F(GltfLoaderTest, SkipsNonTrianglePrimitivesAndReadsNonIndexedOnes) {
  gltf_test::TestAsset asset = gltf_test::positionsAsset({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {});
  Json points = asset.json["meshes"][0]["primitives"][0];
  points["mode"] = 0;
  asset.json["meshes"][0]["primitives"].push_back(points);
  const MeshData mesh = loadGltfMesh(asset.writeGlb(dir_.path(), "mixed"));
  EXPECT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST_F(GltfLoaderTest, ReadsFloatVec3AndUnsignedShortColours) {
  gltf_test::TestAsset asset = gltf_test::quadAsset();
  const std::vector<glm::vec3> rgb(4, glm::vec3(0.25f, 0.5f, 1.0f));
  const int floatView = asset.addView(rgb.data(), sizeof(glm::vec3) * 4);
  Json& attributes = asset.json["meshes"][0]["primitives"][0]["attributes"];
  attributes["COLOR_0"] = asset.addAccessor(floatView, gltf_test::kFloat, 4, "VEC3");
  MeshData mesh = loadGltfMesh(asset.writeGltf(dir_.path(), "rgb"));
  EXPECT_EQ(mesh.colors[2], glm::vec4(0.125f, 0.5f, 1.0f, 1.0f));  // alpha 1, times the factor

  const std::vector<std::uint16_t> rgba16 = {65535, 0, 65535, 0,     0,     65535, 0,     65535,
                                             0,     0, 0,     65535, 65535, 65535, 65535, 65535};
  const int shortView = asset.addView(rgba16.data(), rgba16.size() * 2);
  attributes["COLOR_0"] = asset.addAccessor(shortView, gltf_test::kUnsignedShort, 4, "VEC4", true);
  mesh = loadGltfMesh(asset.writeGltf(dir_.path(), "rgba16"));
  EXPECT_EQ(mesh.colors[0], glm::vec4(0.5f, 0.0f, 1.0f, 0.0f));
  EXPECT_EQ(mesh.colors[1], glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
}

TEST_F(GltfLoaderTest, InstancesEveryNodeThatDrawsTheMesh) {
  gltf_test::TestAsset asset = gltf_test::quadAsset();
  asset.json["nodes"] = Json::array(
      {Json{{"mesh", 0}, {"children", {1}}}, Json{{"mesh", 0}, {"translation", {0, 3, 0}}}});
  const MeshData mesh = loadGltfMesh(asset.writeGltf(dir_.path(), "instances"));
  ASSERT_EQ(mesh.positions.size(), 8u);
  EXPECT_EQ(mesh.positions[7], glm::vec3(0, 4, 0));
  EXPECT_EQ(mesh.boundsMax, glm::vec3(1, 4, 0));
  EXPECT_EQ(mesh.indices.size(), 12u);
}

TEST_F(GltfLoaderTest, DecodesTheBaseColourTextureFromABufferViewOrAFile) {
  const std::vector<std::uint8_t> pixels = {255, 0, 0,   255, 0,  255, 0,  255,  //
                                            0,   0, 255, 255, 10, 20,  30, 40};
  const std::vector<std::uint8_t> png = gltf_test::encodePng(2, 2, pixels);
  gltf_test::TestAsset asset = gltf_test::quadAsset();
  gltf_test::addBaseColorPng(asset, png);
  const MeshData fromView = loadGltfMesh(asset.writeGlb(dir_.path(), "textured"));
  EXPECT_EQ(fromView.baseColorTexture.width, 2u);
  EXPECT_EQ(fromView.baseColorTexture.height, 2u);
  EXPECT_EQ(fromView.baseColorTexture.pixels, pixels);

  gltf_test::writeBytes(dir_.path() / "albedo.png", png);
  asset.json["images"][0] = {{"uri", "albedo.png"}};
  const MeshData fromFile = loadGltfMesh(asset.writeGltf(dir_.path(), "textured_file"));
  EXPECT_EQ(fromFile.baseColorTexture.pixels, pixels);
}

TEST_F(GltfLoaderTest, LoadsExternalFilesFromSubfolders) {
  const gltf_test::TestAsset asset = gltf_test::quadAsset();
  std::filesystem::create_directories(dir_.path() / "data");
  gltf_test::writeBytes(dir_.path() / "data" / "quad data.bin", asset.bin);
  gltf_test::TestAsset moved = asset;
  moved.json["buffers"][0]["uri"] = "data/quad%20data.bin";  // percent-encoded space
  EXPECT_EQ(loadGltfMesh(moved.writeGltf(dir_.path(), "moved")).positions.size(), 4u);
}

}  // namespace
