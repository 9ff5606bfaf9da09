// The weather map on lavapipe: the maxima that empty-space skipping reads match the CPU's, a map
// prepared a band of rows per frame equals one generated at once, and the weather a host reads
// over a column (clouds::proceduralWeatherAt) is the map's texel there.
#include <gtest/gtest.h>

#include "cloud_density.h"
#include "cloud_gpu_fixture.h"
#include "cpu_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using clouds::tools::CloudView;
using test::cumulusView;
using test::kExtent;
using CloudWeather = test::CloudGpuTest;

TEST_F(CloudWeather, GpuWeatherMaximaMatchTheCpu) {
  auto r = renderer();
  r->render(cumulusView(), clouds::Settings{}, kExtent);
  const std::vector<std::uint8_t> weather = r->readWeatherMap();
  const std::vector<std::uint8_t> expected = clouds::tools::weatherMaxima(
      weather, clouds::shader::kWeatherMapSize, clouds::shader::kWeatherMaxFineSize);
  EXPECT_EQ(r->readWeatherMaxFine(), expected);
  // The maxima must be able to say "empty": this map has cells without any coverage.
  int emptyCells = 0;
  for (std::size_t i = 0; i < expected.size(); i += 4) emptyCells += expected[i] == 0 ? 1 : 0;
  EXPECT_GT(emptyCells, 0);
}

TEST_F(CloudWeather, AWeatherMapPreparedOverFramesEqualsOneGeneratedAtOnce) {
  // 30 frames per one-second weather period: the next period's map is generated a band of
  // rows per frame; at t = 1 s it is swapped in. A fresh renderer generates it at once.
  clouds::Settings settings;
  settings.weatherUpdateSeconds = 1.0f;
  settings.weatherEvolutionPerSecond = 0.01f;  // fast enough that periods differ visibly
  CloudView view = cumulusView();
  auto running = renderer();
  const std::vector<std::uint8_t> first = [&] {
    view.timeSeconds = 0.0;
    running->render(view, settings, kExtent);
    return running->readWeatherMap();
  }();
  for (int frame = 1; frame <= 31; ++frame) {
    view.timeSeconds = frame / 30.0;
    running->render(view, settings, kExtent);
    if (frame < 30) {
      // Still period 0 while period 1 is being prepared in the other map.
      ASSERT_EQ(running->readWeatherMap(), first) << "frame " << frame;
    }
  }
  auto fresh = renderer();
  fresh->render(view, settings, kExtent);
  const std::vector<std::uint8_t> prepared = running->readWeatherMap();
  EXPECT_NE(prepared, first);
  EXPECT_EQ(prepared, fresh->readWeatherMap());
  EXPECT_EQ(running->readWeatherMaxFine(), fresh->readWeatherMaxFine());
}

// Over every 8th texel centre of the map, what a host reads for the column equals the GPU's texel
// decoded under the settings, to the texel's 8-bit quantisation.
TEST_F(CloudWeather, TheWeatherAHostReadsIsTheMapsTexel) {
  clouds::Settings settings;
  settings.coverage = 0.6f;
  settings.cloudType = 0.8f;
  CloudView view = cumulusView();
  view.timeSeconds = 0.0;
  auto r = renderer();
  r->render(view, settings, kExtent);
  const std::vector<std::uint8_t> map = r->readWeatherMap();
  const std::uint32_t size = clouds::shader::kWeatherMapSize;
  ASSERT_EQ(map.size(), std::size_t{size} * size * 4);
  clouds::shader::CloudUniforms u{};
  u.coverage = settings.coverage;
  u.cloudType = settings.cloudType;
  u.typeVariation = settings.typeVariation;
  u.densityVariation = settings.densityVariation;
  u.layerDensityScale = 1.0f;
  double worst = 0.0;
  std::size_t covered = 0;
  for (std::uint32_t y = 0; y < size; y += 8) {
    for (std::uint32_t x = 0; x < size; x += 8) {
      const std::uint8_t* t = &map[(std::size_t{y} * size + x) * 4];
      const glm::vec4 texel(t[0] / 255.0f, t[1] / 255.0f, t[2] / 255.0f, t[3] / 255.0f);
      const clouds::shader::WeatherSample gpu =
          clouds::shader::decodeWeather(texel, clouds::shader::surroundingWeather(u), u);
      // A column a whole number of tiles away: the map repeats.
      const glm::dvec2 column =
          (glm::dvec2(x, y) + 0.5) / double(size) * double(settings.weatherTileMetres) -
          3.0 * double(settings.weatherTileMetres);
      const clouds::WeatherColumn cpu = clouds::proceduralWeatherAt(settings, 1, column, 0.0);
      worst = std::max({worst, std::abs(double(cpu.coverage) - gpu.coverage),
                        std::abs(double(cpu.type) - gpu.type),
                        std::abs(double(cpu.density) - gpu.density)});
      covered += cpu.coverage > 0.5f ? 1 : 0;
    }
  }
  std::printf("weather columns: worst difference %.5f, %zu of 4096 over half covered\n", worst,
              covered);
  EXPECT_LE(worst, 0.6 / 255.0 + 1e-5) << "within the texel's rounding";
  EXPECT_GT(covered, 100u) << "a map with cloud in it";
  EXPECT_LT(covered, 4000u) << "and clear sky";
}

}  // namespace
