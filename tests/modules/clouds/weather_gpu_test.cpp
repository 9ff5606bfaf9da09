// The weather map on lavapipe: the maxima that empty-space skipping reads match the CPU's, and
// a map prepared a band of rows per frame equals one generated at once.
#include <gtest/gtest.h>

#include "cloud_gpu_fixture.h"
#include "cpu_reference.h"

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

}  // namespace
