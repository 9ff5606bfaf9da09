// The standalone generator's textures (clouds/procedural_textures.h, tools/clouds/generator) are
// the module's: each CPU texel rounds to the byte the GPU's generator stored, within one 8-bit
// step, for the shape, detail and curl noise and the weather map at two moments; and a painted
// map written from the CPU map through a PNG shows the procedural clouds of that moment.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>

#include "cloud_gpu_fixture.h"
#include "cloud_types.h"
#include "clouds/procedural_textures.h"
#include "engine/assets/image_io.h"
#include "engine/gfx/upload.h"

namespace {

using clouds::tools::CloudView;
using ProceduralTextures = test::SharedHarnessTest<96, 54>;

// How far the CPU's bytes are from the GPU's, over `count` texels.
struct ByteAgreement {
  int worstSteps = 0;
  std::size_t differing = 0;
  std::size_t count = 0;
};

ByteAgreement compare(std::size_t count, const std::function<std::uint8_t(std::size_t)>& gpu,
                      const std::function<float(std::size_t)>& cpu) {
  ByteAgreement a;
  a.count = count;
  for (std::size_t i = 0; i < count; ++i) {
    const int steps = std::abs(int(gpu(i)) - int(clouds::storedUnorm8(cpu(i))));
    a.worstSteps = std::max(a.worstSteps, steps);
    a.differing += steps != 0 ? 1u : 0u;
  }
  return a;
}

// Within one step everywhere, and off by one in at most one texel in a thousand (float
// evaluation order differs between the shader compiler and the C++ compiler only in the last
// bits, which move a value across a rounding boundary rarely).
void expectSameBytes(const ByteAgreement& a, const char* what) {
  std::printf("%s: %zu of %zu texels differ, by at most %d step(s)\n", what, a.differing, a.count,
              a.worstSteps);
  EXPECT_LE(a.worstSteps, 1) << what;
  EXPECT_LE(double(a.differing), 1e-3 * double(a.count)) << what;
}

// The textures of a context that has rendered one frame at `timeSeconds`.
void renderAt(clouds::tools::CloudHarness& harness, double timeSeconds) {
  CloudView view;
  view.timeSeconds = timeSeconds;
  harness.render(view, clouds::tools::singleFrame(clouds::Settings{}), {96, 54});
}

TEST_F(ProceduralTextures, TheNoiseVolumesAreTheGpusTexels) {
  renderAt(harness(), 0.0);
  const std::uint32_t seed = clouds::tools::HarnessOptions{}.noiseSeed;
  // Level 0 of each packed chain holds each texel's own value in R (noise_mip.comp).
  const auto volume = [&](const std::vector<std::uint8_t>& chain, int size,
                          std::vector<float> (*slice)(std::uint32_t, int), const char* what) {
    std::vector<float> cpu;
    for (int z = 0; z < size; ++z) {
      const std::vector<float> s = slice(seed, z);
      cpu.insert(cpu.end(), s.begin(), s.end());
    }
    expectSameBytes(compare(
                        cpu.size(), [&](std::size_t i) { return chain[4 * i]; },
                        [&](std::size_t i) { return cpu[i]; }),
                    what);
  };
  volume(harness().readShapeNoise(), clouds::kShapeNoiseTexels, clouds::shapeNoiseSlice,
         "shape noise");
  volume(harness().readDetailNoise(), clouds::kDetailNoiseTexels, clouds::detailNoiseSlice,
         "detail noise");
  const std::vector<std::uint8_t> gpuCurl = harness().readCurlNoise();
  const std::vector<glm::vec2> curl = clouds::curlNoise(seed);
  expectSameBytes(compare(
                      2 * curl.size(), [&](std::size_t i) { return gpuCurl[4 * (i / 2) + i % 2]; },
                      [&](std::size_t i) { return curl[i / 2][int(i % 2)]; }),
                  "curl noise");
}

TEST_F(ProceduralTextures, TheWeatherMapIsTheGpusAtEachMoment) {
  const clouds::Settings settings;
  const std::uint32_t seed = clouds::tools::HarnessOptions{}.noiseSeed;
  // 0 s and a moment many periods later, whose map has evolved (phase 0.5).
  for (const double time : {0.0, 1000.0}) {
    renderAt(harness(), time);
    const float phase = clouds::proceduralWeatherPhase(settings, time);
    const std::vector<std::uint8_t> gpu = harness().readWeatherMap();
    const std::vector<glm::vec4> cpu = clouds::proceduralWeatherMap(seed, phase);
    char what[64];
    std::snprintf(what, sizeof what, "weather map at %.0f s (phase %.4f)", time, double(phase));
    expectSameBytes(compare(
                        3 * cpu.size(), [&](std::size_t i) { return gpu[4 * (i / 3) + i % 3]; },
                        [&](std::size_t i) { return cpu[i / 3][int(i % 3)]; }),
                    what);
  }
}

TEST_F(ProceduralTextures, APaintedMapWrittenFromTheGeneratorShowsTheSameClouds) {
  const std::uint32_t seed = clouds::tools::HarnessOptions{}.noiseSeed;
  const std::vector<glm::vec4> cpu = clouds::proceduralWeatherMap(seed, 0.0f);
  // Through the file an artist would paint over.
  engine::assets::ImageRgba8 png{clouds::kWeatherMapTexels, clouds::kWeatherMapTexels, {}};
  for (const glm::vec4& t : cpu) {
    for (int c = 0; c < 4; ++c) png.pixels.push_back(clouds::storedUnorm8(t[c]));
  }
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "clouds_painted_weather_map.png";
  engine::assets::writePng(file, png);
  const engine::assets::ImageRgba32f read = engine::assets::readImage(file);
  std::filesystem::remove(file);
  std::vector<std::uint8_t> texels;
  for (const float v : read.pixels) texels.push_back(clouds::storedUnorm8(v));
  ASSERT_EQ(texels, png.pixels) << "the PNG does not keep the map's bytes";

  engine::gfx::Image painted(
      device(), engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                       VK_FORMAT_R8G8B8A8_UNORM,
                                       {read.width, read.height, 1},
                                       1,
                                       1,
                                       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                       "painted weather"});
  engine::gfx::uploadToImage(device(), painted, std::as_bytes(std::span(texels)),
                             engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  // Each in the first frame of its own context: a single frame's samples are jittered by the
  // frame's place in its sequence.
  CloudView view;
  view.pitchDegrees = 6.0;
  const clouds::Settings settings = clouds::tools::singleFrame(clouds::Settings{});
  clouds::tools::CloudHarness proceduralHost(device(), {96, 54});
  const clouds::tools::CloudFrame procedural = proceduralHost.render(view, settings, {96, 54});
  clouds::tools::CloudHarness paintedHost(device(), {96, 54});
  view.weatherView = painted.view();
  const clouds::tools::CloudFrame fromPainting = paintedHost.render(view, settings, {96, 54});
  // A 512^2 painting resamples texel for texel; the procedural map differs from the CPU's in a
  // few texels by one step (above).
  EXPECT_EQ(paintedHost.readWeatherMap(), texels) << "the module changed the painted bytes";
  double opacity = 0.0;
  for (const glm::vec4& p : procedural.radiance) opacity += 1.0 - p.a;
  opacity /= double(procedural.radiance.size());
  const double db = clouds::tools::psnr(fromPainting.radiance, procedural.radiance, 1.0);
  std::printf("mean opacity %.3f; painted against procedural: %.1f dB\n", opacity, db);
  ASSERT_GT(opacity, 0.03) << "the view shows too little cloud to compare";
  EXPECT_GT(db, 60.0);
}

}  // namespace
