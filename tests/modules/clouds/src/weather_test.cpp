// Weather states and the timeline (clouds/weather.h), without a GPU: the built-in states, the
// blend, the schedule's phases at any time, the wind's displacement as the integral of the
// blended wind, and a transition slow enough to keep the temporal history frame by frame.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "clouds/weather.h"
#include "temporal_state.h"

namespace {

using clouds::WeatherKey;
using clouds::WeatherPreset;
using clouds::WeatherState;
using clouds::WeatherTimeline;

WeatherState preset(WeatherPreset p) {
  return clouds::weatherPreset(p);
}

WeatherTimeline sparseToStormy(bool repeat) {
  const WeatherKey keys[] = {{preset(WeatherPreset::Sparse), 30.0, 20.0},
                             {preset(WeatherPreset::Stormy), 40.0, 10.0}};
  std::string error;
  const auto timeline = WeatherTimeline::schedule(keys, repeat, &error);
  EXPECT_TRUE(timeline) << error;
  return *timeline;
}

TEST(Weather, TheBuiltInStatesAreValidAndNamed) {
  for (WeatherPreset p : clouds::kWeatherPresets) {
    EXPECT_EQ(clouds::validateWeatherState(preset(p)), "") << clouds::weatherPresetName(p);
    WeatherPreset parsed = WeatherPreset::Sparse;
    std::string upper = clouds::weatherPresetName(p);
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    ASSERT_TRUE(clouds::parseWeatherPreset(upper, &parsed)) << upper;
    EXPECT_EQ(parsed, p);
  }
  WeatherPreset untouched = WeatherPreset::Cloudy;
  EXPECT_FALSE(clouds::parseWeatherPreset("drizzle", &untouched));
  EXPECT_EQ(untouched, WeatherPreset::Cloudy);
  // Fairest first, and only the storm strikes, towers into anvils and goes dark.
  EXPECT_LT(preset(WeatherPreset::Sparse).coverage, preset(WeatherPreset::Cloudy).coverage);
  EXPECT_LT(preset(WeatherPreset::Cloudy).coverage, preset(WeatherPreset::Overcast).coverage);
  EXPECT_LT(preset(WeatherPreset::Overcast).cloudType, 0.5f) << "a stratus deck";
  for (WeatherPreset p : {WeatherPreset::Sparse, WeatherPreset::Cloudy, WeatherPreset::Overcast}) {
    EXPECT_EQ(preset(p).lightningStrikesPerMinute, 0.0f);
    EXPECT_EQ(preset(p).anvilBias, 0.0f);
    EXPECT_LT(preset(p).densityMultiplier, preset(WeatherPreset::Stormy).densityMultiplier);
  }
  EXPECT_GT(preset(WeatherPreset::Stormy).lightningStrikesPerMinute, 0.0f);
  EXPECT_EQ(preset(WeatherPreset::Stormy).anvilBias, 1.0f);
}

TEST(Weather, SettingsCarryAStateBothWays) {
  const WeatherState storm = preset(WeatherPreset::Stormy);
  clouds::Settings s;
  s.layerTopMetres = 9000.0f;
  const clouds::Settings stormy = clouds::withWeather(s, storm);
  EXPECT_EQ(stormy.layerTopMetres, 9000.0f) << "the layer is not the weather";
  WeatherState back = clouds::weatherOf(stormy);
  EXPECT_EQ(back.lightningStrikesPerMinute, 0.0f) << "the module strikes nothing itself";
  back.lightningStrikesPerMinute = storm.lightningStrikesPerMinute;
  EXPECT_EQ(back, storm);
}

TEST(Weather, ABadStateIsNamedByItsField) {
  WeatherState w;
  w.coverage = 2.0f;
  EXPECT_EQ(clouds::validateWeatherState(w).rfind("WeatherState.coverage = 2", 0), 0u)
      << clouds::validateWeatherState(w);
  w = {};
  w.lightningStrikesPerMinute = -1.0f;
  EXPECT_NE(clouds::validateWeatherState(w).find("lightningStrikesPerMinute"), std::string::npos);
  w = {};
  w.windDirection = {0.0f, 0.0f};
  EXPECT_NE(clouds::validateWeatherState(w).find("WeatherState.windDirection"), std::string::npos);
  w = {};
  w.densityMultiplier = std::nanf("");
  EXPECT_NE(clouds::validateWeatherState(w).find("densityMultiplier"), std::string::npos);
}

TEST(Weather, TheBlendEndsAtEachStateAndTurnsTheWindTheShortWay) {
  WeatherState a = preset(WeatherPreset::Sparse);
  WeatherState b = preset(WeatherPreset::Stormy);
  a.windDirection = {1.0f, 0.0f};
  a.windSpeedMetresPerSecond = 10.0f;
  b.windDirection = {0.0f, 2.0f};  // any length
  b.windSpeedMetresPerSecond = 10.0f;
  const WeatherState start = clouds::blendWeather(a, b, 0.0f);
  const WeatherState end = clouds::blendWeather(a, b, 1.0f);
  EXPECT_EQ(start.coverage, a.coverage);
  EXPECT_EQ(end.coverage, b.coverage);
  EXPECT_EQ(end.lightningStrikesPerMinute, b.lightningStrikesPerMinute);
  EXPECT_NEAR(end.windDirection.y, 1.0f, 1e-6f);
  const WeatherState half = clouds::blendWeather(a, b, 0.5f);
  EXPECT_NEAR(half.coverage, 0.5f * (a.coverage + b.coverage), 1e-6f);
  EXPECT_NEAR(half.windDirection.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(half.windDirection.y, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(half.windSpeedMetresPerSecond, 10.0f * std::sqrt(0.5f), 1e-4f);
  // Opposite winds pass through a calm that keeps a direction.
  b.windDirection = {-1.0f, 0.0f};
  const WeatherState calm = clouds::blendWeather(a, b, 0.5f);
  EXPECT_NEAR(calm.windSpeedMetresPerSecond, 0.0f, 1e-5f);
  EXPECT_EQ(clouds::validateWeatherState(calm), "");
}

TEST(Weather, AScheduleHoldsThenBlendsEasedAndRepeats) {
  const WeatherTimeline t = sparseToStormy(true);
  const WeatherState sparse = preset(WeatherPreset::Sparse);
  const WeatherState storm = preset(WeatherPreset::Stormy);
  EXPECT_EQ(t.stateAt(0.0), sparse);
  EXPECT_EQ(t.stateAt(29.9), sparse);
  // Halfway through the 20 s transition the smoothstep is at one half; a quarter in, at 5/32.
  EXPECT_NEAR(t.stateAt(40.0).coverage, 0.5f * (sparse.coverage + storm.coverage), 1e-6f);
  EXPECT_NEAR(t.stateAt(35.0).coverage,
              sparse.coverage + (storm.coverage - sparse.coverage) * 0.15625f, 1e-6f);
  const clouds::WeatherPhase phase = t.phaseAt(35.0);
  EXPECT_EQ(phase.from, 0u);
  EXPECT_EQ(phase.to, 1u);
  EXPECT_NEAR(phase.blend, 0.15625f, 1e-6f);
  EXPECT_EQ(t.stateAt(50.0), storm);
  EXPECT_EQ(t.stateAt(89.9), storm);
  // The storm blends back into sparse over 10 s, and the 100 s cycle begins again.
  EXPECT_NEAR(t.stateAt(95.0).anvilBias, 0.5f, 1e-6f);
  EXPECT_EQ(t.stateAt(100.0), sparse);
  EXPECT_EQ(t.stateAt(1e6 + 40.0), t.stateAt(40.0)) << "1e6 s is 10 000 whole cycles";
  // Without repeat, the last state stays.
  const WeatherTimeline once = sparseToStormy(false);
  EXPECT_EQ(once.stateAt(95.0), storm);
  EXPECT_EQ(once.stateAt(1e6), storm);
}

TEST(Weather, ABadScheduleIsRefusedNamingTheKey) {
  std::string error;
  EXPECT_FALSE(WeatherTimeline::schedule({}, true, &error));
  EXPECT_NE(error.find("at least one"), std::string::npos) << error;
  WeatherKey keys[] = {{preset(WeatherPreset::Sparse), 10.0, 10.0},
                       {preset(WeatherPreset::Cloudy), -1.0, 10.0}};
  EXPECT_FALSE(WeatherTimeline::schedule(keys, true, &error));
  EXPECT_NE(error.find("WeatherKey[1].holdSeconds = -1"), std::string::npos) << error;
  keys[1].holdSeconds = 10.0;
  keys[1].state.coverage = -0.5f;
  EXPECT_FALSE(WeatherTimeline::schedule(keys, true, &error));
  EXPECT_NE(error.find("WeatherKey[1]: WeatherState.coverage"), std::string::npos) << error;
  keys[1].state.coverage = 0.5f;
  keys[0].transitionSeconds = std::nan("");
  EXPECT_FALSE(WeatherTimeline::schedule(keys, true, &error));
  EXPECT_NE(error.find("transitionSeconds"), std::string::npos) << error;
  const WeatherKey instant[] = {{preset(WeatherPreset::Sparse), 0.0, 0.0}};
  EXPECT_FALSE(WeatherTimeline::schedule(instant, true, &error));
  EXPECT_TRUE(WeatherTimeline::schedule(instant, false, &error)) << "steady weather";
}

// The displacement's rate of change is the blended wind's velocity at every time (a central
// difference), and it has no jump anywhere: across holds, transitions and cycles.
TEST(Weather, TheWindsDisplacementIsTheIntegralOfTheBlendedWind) {
  WeatherTimeline t = sparseToStormy(true);
  WeatherState turned = preset(WeatherPreset::Stormy);
  turned.windDirection = {-0.3f, 1.0f};
  const WeatherKey keys[] = {{preset(WeatherPreset::Sparse), 30.0, 20.0}, {turned, 40.0, 10.0}};
  t = *WeatherTimeline::schedule(keys, true, nullptr);
  const double h = 1e-3;
  for (double time = 0.5; time < 250.0; time += 0.37) {
    const glm::dvec2 rate =
        (t.windDisplacementAt(time + h) - t.windDisplacementAt(time - h)) / (2.0 * h);
    const glm::dvec2 velocity = clouds::windVelocity(t.stateAt(time));
    ASSERT_NEAR(rate.x, velocity.x, 1e-4) << time;
    ASSERT_NEAR(rate.y, velocity.y, 1e-4) << time;
  }
  // Against a brute-force integral (midpoint rule, 1 ms steps) over two and a half cycles.
  glm::dvec2 integral(0.0);
  const double step = 1e-3;
  for (double time = 0.5 * step; time < 250.0; time += step) {
    integral += clouds::windVelocity(t.stateAt(time)) * step;
  }
  EXPECT_NEAR(t.windDisplacementAt(250.0).x, integral.x, 1e-3);
  EXPECT_NEAR(t.windDisplacementAt(250.0).y, integral.y, 1e-3);
  // After an hour and after 1e6 s: a cycle's displacement per cycle, to the millimetre.
  const glm::dvec2 cycle = t.windDisplacementAt(100.0);
  for (double cycles : {36.0, 10000.0}) {
    const glm::dvec2 far = t.windDisplacementAt(cycles * 100.0 + 40.0);
    const glm::dvec2 expected = cycle * cycles + t.windDisplacementAt(40.0);
    EXPECT_NEAR(far.x, expected.x, 1e-3) << cycles;
    EXPECT_NEAR(far.y, expected.y, 1e-3) << cycles;
  }
}

TEST(Weather, AChangeAskedForInPlayStartsWhereTheWeatherIs) {
  WeatherTimeline t = sparseToStormy(true);
  const double at = 40.0;  // halfway into sparse -> stormy
  const WeatherState before = t.stateAt(at);
  const glm::dvec2 carried = t.windDisplacementAt(at);
  const WeatherState overcast = preset(WeatherPreset::Overcast);
  t.transitionTo(overcast, at, 15.0);
  EXPECT_EQ(t.stateAt(at), before);
  EXPECT_EQ(t.windDisplacementAt(at), carried);
  EXPECT_NEAR(t.stateAt(at + 7.5).coverage, 0.5f * (before.coverage + overcast.coverage), 1e-6f);
  EXPECT_EQ(t.stateAt(at + 15.0), overcast);
  EXPECT_EQ(t.stateAt(1e6), overcast) << "the schedule's repeat ended";
  EXPECT_FALSE(t.repeats());
  const glm::dvec2 rate =
      (t.windDisplacementAt(at + 1e-3) - t.windDisplacementAt(at - 1e-3)) / 2e-3;
  EXPECT_NEAR(rate.x, clouds::windVelocity(before).x, 1e-3) << "no kink where the change begins";
}

// Frame by frame at 30 fps, a 20 s transition between any two built-in states moves no field
// far enough to drop the temporal history; the same change at once does.
TEST(Weather, ATwentySecondTransitionKeepsTheHistoryEveryFrame) {
  const clouds::Settings base = clouds::settingsFor(clouds::Quality::Medium);
  for (WeatherPreset from : clouds::kWeatherPresets) {
    for (WeatherPreset to : clouds::kWeatherPresets) {
      if (from == to) continue;
      const WeatherKey keys[] = {{preset(from), 1.0, 20.0}, {preset(to), 1.0, 0.0}};
      const WeatherTimeline t = *WeatherTimeline::schedule(keys, false, nullptr);
      clouds::Settings previous = clouds::withWeather(base, t.stateAt(0.0));
      for (int frame = 1; frame <= 30 * 22; ++frame) {
        const clouds::Settings now = clouds::withWeather(base, t.stateAt(frame / 30.0));
        ASSERT_FALSE(clouds::detail::cloudsLookDifferent(previous, now))
            << clouds::weatherPresetName(from) << " -> " << clouds::weatherPresetName(to)
            << " at frame " << frame;
        previous = now;
      }
      EXPECT_TRUE(clouds::detail::cloudsLookDifferent(clouds::withWeather(base, preset(from)),
                                                      clouds::withWeather(base, preset(to))));
    }
  }
}

}  // namespace
