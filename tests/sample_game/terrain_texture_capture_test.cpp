// A user's glTF terrain with a base colour texture is coloured by it (the glTF's rule: vertex
// colour times texture), as the sample renders it headless: a flat 4 km square with a black and
// white checker of 1 km squares, seen from 1.5 km straight above its middle (where four squares
// meet), against the same square without its texture.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/assets/image_io.h"
#include "gltf_test_asset.h"
#include "sample_runs.h"

namespace {

namespace fs = std::filesystem;
using engine::assets::ImageRgba32f;
using namespace sample_tests;

// The quad (gltf_test_asset.h) laid flat (turned -90 degrees about x: its +z normal points up)
// and scaled to 4 km (the sample centres a terrain and sets it on sea level), uncoloured; with
// `checker`, a 16x16 texture of 4x4 black and white squares.
fs::path writeTerrain(const fs::path& dir, bool checker) {
  gltf_test::TestAsset asset = gltf_test::quadAsset();
  asset.json["meshes"][0]["primitives"][0]["attributes"].erase("COLOR_0");
  asset.json["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, 1.0, 1.0, 1.0};
  asset.json["nodes"][0]["rotation"] = {-0.70710678, 0.0, 0.0, 0.70710678};
  asset.json["nodes"][0]["scale"] = {4000.0, 4000.0, 4000.0};
  if (checker) {
    std::vector<std::uint8_t> rgba;
    for (std::uint32_t y = 0; y < 16; ++y) {
      for (std::uint32_t x = 0; x < 16; ++x) {
        const std::uint8_t v = ((x / 4 + y / 4) % 2 == 0) ? 255 : 0;
        rgba.insert(rgba.end(), {v, v, v, 255});
      }
    }
    gltf_test::addBaseColorPng(asset, gltf_test::encodePng(16, 16, rgba));
  }
  return asset.writeGltf(dir, checker ? "checker" : "plain");
}

// The frame from 1.5 km straight above the square's middle, 128x72, HDR.
ImageRgba32f render(const char* name, bool checker) {
  const fs::path dir = freshDir(name);
  fs::create_directories(dir);
  const fs::path terrain = writeTerrain(dir, checker);
  const std::string sceneJson = R"({"name": "a textured square",
    "camera": {"position": [0, 1500, 0], "pitchDegrees": -89, "speedMetresPerSecond": 0},
    "sun": {"timeOfDayHours": 12}, "terrain": {"gltf": ")" +
                                terrain.filename().string() + R"("},
    "exposure": {"mode": "manual", "ev100": 14}})";
  return renderLastFrame(dir, sceneJson, 3, 128, 72);
}

std::vector<float> luminances(const ImageRgba32f& image) {
  std::vector<float> values;
  for (std::size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
    values.push_back(0.2126f * image.pixels[i] + 0.7152f * image.pixels[i + 1] +
                     0.0722f * image.pixels[i + 2]);
  }
  std::sort(values.begin(), values.end());
  return values;
}

TEST(UserTerrainTexture, ItsBaseColourTextureColoursTheGround) {
  const std::vector<float> checker = luminances(render("textured_terrain", true));
  const std::vector<float> plain = luminances(render("plain_terrain", false));
  ASSERT_FALSE(checker.empty());
  ASSERT_EQ(checker.size(), plain.size());
  const auto percentile = [](const std::vector<float>& v, double p) {
    return v[std::size_t(p * double(v.size() - 1))];
  };
  const float dark = percentile(checker, 0.1), bright = percentile(checker, 0.9);
  const float plainLow = percentile(plain, 0.1), plainHigh = percentile(plain, 0.9);
  std::printf("textured: 10th %.4g, 90th %.4g; plain: 10th %.4g, 90th %.4g\n", dark, bright,
              plainLow, plainHigh);
  // The black squares take only the sky's haze: far darker than the white ones.
  EXPECT_GT(bright, 5.0f * dark) << "the checker shows";
  EXPECT_LT(plainHigh, 1.5f * plainLow) << "without the texture the square is even";
  // The white squares are the untextured ground's white (the texture multiplies, not replaces).
  EXPECT_NEAR(bright, plainHigh, 0.15f * plainHigh);
}

}  // namespace
