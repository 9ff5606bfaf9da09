// Weather regions as plain logic: a region's strength over distance and its shape, the order
// regions apply in, the cell ceiling empty-space skipping trusts (an upper bound over random
// cells), the uniforms (no regions: the bits before regions existed; far from the origin:
// placed about the camera), how far regions moved between frames, the look led ahead, and the
// column query hosts place things with.
#include <gtest/gtest.h>

#include <random>

#include "cloud_weather_regions.h"
#include "clouds/clouds.h"
#include "clouds/procedural_textures.h"
#include "clouds/weather.h"
#include "temporal_state.h"
#include "uniforms.h"
#include "weather_regions.h"

namespace {

using clouds::WeatherRegion;
namespace shader = clouds::shader;
namespace detail = clouds::detail;

// The uniforms of a frame at `camera` (x, z) with `regions` over settings `s`.
shader::CloudUniforms uniformsWith(std::vector<WeatherRegion> regions,
                                   const clouds::Settings& s = {}, glm::dvec2 camera = {}) {
  clouds::FrameInputs in;
  in.cameraPosition = {camera.x, 500.0, camera.y};
  in.weatherRegions = regions;
  return detail::buildUniforms(in, s, detail::UniformContext{});
}

WeatherRegion disc(glm::dvec2 centre, float radius, float blend, float coverage) {
  WeatherRegion r;
  r.centreMetres = centre;
  r.radiusMetres = radius;
  r.blendMetres = blend;
  r.coverage = coverage;
  return r;
}

TEST(WeatherRegions, ARegionHoldsItsLookInsideAndEasesOutOverItsBlend) {
  clouds::Settings s;
  s.coverage = 0.2f;
  const shader::CloudUniforms u = uniformsWith({disc({1000.0, 0.0}, 2000.0f, 4000.0f, 0.9f)}, s);
  const auto coverageAt = [&](float x) {
    return shader::columnWeather(glm::vec2(x, 0.0f), u).coverage;
  };
  EXPECT_FLOAT_EQ(coverageAt(1000.0f), 0.9f);
  EXPECT_FLOAT_EQ(coverageAt(2999.0f), 0.9f);      // within the radius
  EXPECT_NEAR(coverageAt(5000.0f), 0.55f, 1e-5f);  // halfway through the blend: smoothstep 0.5
  EXPECT_FLOAT_EQ(coverageAt(7000.0f), 0.2f);      // past it: the surroundings'
  EXPECT_FLOAT_EQ(coverageAt(-50000.0f), 0.2f);
  float last = 1.0f;
  for (float x = 3000.0f; x <= 7000.0f; x += 100.0f) {
    EXPECT_LE(coverageAt(x), last) << x;  // falls all the way
    last = coverageAt(x);
  }
}

TEST(WeatherRegions, ARectangleIsTurnedByItsHeading) {
  clouds::Settings s;
  s.coverage = 0.0f;
  WeatherRegion front = disc({0.0, 0.0}, 0.0f, 100.0f, 1.0f);
  front.halfSidesMetres = {10000.0f, 500.0f};  // 20 km long, 1 km wide
  front.headingDegrees = 30.0f;                // its length 30 degrees counter-clockwise of +x
  const shader::CloudUniforms u = uniformsWith({front}, s);
  const auto coverageAt = [&](float x, float z) {
    return shader::columnWeather(glm::vec2(x, z), u).coverage;
  };
  // Along its length: +x turned towards -z (x, z) = 9 km (cos 30, -sin 30); across it, 400 m.
  const glm::vec2 along(std::cos(glm::radians(30.0f)), -std::sin(glm::radians(30.0f)));
  const glm::vec2 across(-along.y, along.x);
  const auto at = [&](glm::vec2 p) { return coverageAt(p.x, p.y); };
  EXPECT_FLOAT_EQ(at(9000.0f * along), 1.0f);
  EXPECT_FLOAT_EQ(at(-9000.0f * along + 400.0f * across), 1.0f);
  EXPECT_FLOAT_EQ(at(600.0f * across), 0.0f);
  EXPECT_FLOAT_EQ(at(10200.0f * along), 0.0f);
  EXPECT_FLOAT_EQ(coverageAt(0.0f, 9000.0f), 0.0f);  // the unturned rectangle's end
}

TEST(WeatherRegions, LaterRegionsApplyOverEarlierOnes) {
  clouds::Settings s;
  s.coverage = 0.1f;
  WeatherRegion first = disc({0.0, 0.0}, 5000.0f, 1000.0f, 0.9f);
  first.cloudType = 1.0f;
  first.anvilBias = 0.7f;
  first.densityMultiplier = 4.0f;
  WeatherRegion second = disc({3000.0, 0.0}, 1000.0f, 1000.0f, 0.3f);
  second.cloudType = 0.0f;
  second.densityMultiplier = 2.0f;
  const shader::CloudUniforms u = uniformsWith({first, second}, s);
  // The densest multiplier sets the extinction; each column scales it.
  EXPECT_FLOAT_EQ(u.extinctionPerMetre, s.extinctionPerMetre * 4.0f);
  EXPECT_FLOAT_EQ(u.layerDensityScale, 0.25f);
  EXPECT_FLOAT_EQ(u.fullestCoverage, 0.9f);
  const shader::ColumnWeather inBoth = shader::columnWeather(glm::vec2(3000.0f, 0.0f), u);
  EXPECT_FLOAT_EQ(inBoth.coverage, 0.3f);
  EXPECT_FLOAT_EQ(inBoth.cloudType, 0.0f);
  EXPECT_FLOAT_EQ(inBoth.densityScale, 0.5f);
  EXPECT_FLOAT_EQ(inBoth.anvilBias, 0.0f);
  const shader::ColumnWeather inFirst = shader::columnWeather(glm::vec2(-3000.0f, 0.0f), u);
  EXPECT_FLOAT_EQ(inFirst.coverage, 0.9f);
  EXPECT_FLOAT_EQ(inFirst.cloudType, 1.0f);
  EXPECT_FLOAT_EQ(inFirst.densityScale, 1.0f);
  EXPECT_FLOAT_EQ(inFirst.anvilBias, 0.7f);
}

// Columns at random in the disc of `radius` about `centre` all lie under the cell's ceiling
// (columnWeatherCeiling()); returns the highest coverage and type among them.
glm::vec2 highestUnderTheCeiling(const shader::CloudUniforms& u, glm::vec2 centre, float radius,
                                 int samples, std::mt19937& random) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const glm::vec2 ceiling = shader::columnWeatherCeiling(centre, radius, u);
  glm::vec2 highest(0.0f);
  for (int k = 0; k < samples; ++k) {
    const float angle = unit(random) * 6.2831853f;
    const glm::vec2 p =
        centre + radius * std::sqrt(unit(random)) * glm::vec2(std::cos(angle), std::sin(angle));
    const shader::ColumnWeather c = shader::columnWeather(p, u);
    EXPECT_LE(c.coverage, ceiling.x + 1e-5f) << p.x << ", " << p.y;
    EXPECT_LE(c.cloudType, ceiling.y + 1e-5f) << p.x << ", " << p.y;
    highest = glm::max(highest, glm::vec2(c.coverage, c.cloudType));
  }
  return highest;
}

TEST(WeatherRegions, TheCellCeilingBoundsEveryColumnInTheCell) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int tight = 0;
  for (int trial = 0; trial < 200; ++trial) {
    clouds::Settings s;
    s.coverage = unit(random);
    s.cloudType = unit(random);
    std::vector<WeatherRegion> regions;
    for (int i = 0; i < 1 + trial % 4; ++i) {
      WeatherRegion r = disc({(unit(random) - 0.5) * 20000.0, (unit(random) - 0.5) * 20000.0},
                             unit(random) * 3000.0f, 100.0f + unit(random) * 5000.0f, unit(random));
      r.halfSidesMetres = {unit(random) * 3000.0f, unit(random) * 1000.0f};
      r.headingDegrees = unit(random) * 360.0f;
      r.cloudType = unit(random);
      regions.push_back(r);
    }
    const shader::CloudUniforms u = uniformsWith(regions, s);
    const glm::vec2 centre((unit(random) - 0.5f) * 20000.0f, (unit(random) - 0.5f) * 20000.0f);
    const float radius = 100.0f + unit(random) * 3000.0f;
    const glm::vec2 ceiling = shader::columnWeatherCeiling(centre, radius, u);
    const glm::vec2 highest = highestUnderTheCeiling(u, centre, radius, 400, random);
    ASSERT_FALSE(HasFailure()) << "trial " << trial;
    tight += ceiling.x - highest.x < 0.05f;
  }
  EXPECT_GT(tight, 100) << "the ceiling is so loose it would skip nothing";
  // A cell of no size: the ceiling is the column's weather.
  const shader::CloudUniforms u = uniformsWith({disc({0.0, 0.0}, 100.0f, 1000.0f, 0.8f)});
  EXPECT_FLOAT_EQ(shader::columnWeatherCeiling(glm::vec2(600.0f, 0.0f), 0.0f, u).x,
                  shader::columnWeather(glm::vec2(600.0f, 0.0f), u).coverage);
}

// A superstorm's look (a clear eye, a full wall, bands) under the ceiling too.
TEST(WeatherRegions, TheCellCeilingBoundsASuperstormsColumns) {
  WeatherRegion storm = disc({0.0, 0.0}, 30000.0f, 10000.0f, 0.6f);
  storm.vortex.eyeRadiusMetres = 3000.0f;
  clouds::Settings s;
  s.weatherRegions = 1;
  s.superstorms = 1;
  const shader::CloudUniforms u = uniformsWith({storm}, s);
  ASSERT_EQ(u.vortexRegion, 0u);
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 100 && !HasFailure(); ++trial) {
    const glm::vec2 centre((unit(random) - 0.5f) * 60000.0f, (unit(random) - 0.5f) * 60000.0f);
    highestUnderTheCeiling(u, centre, 100.0f + unit(random) * 3000.0f, 200, random);
  }
}

TEST(WeatherRegions, WithoutRegionsTheUniformsAreTheSkysAlone) {
  clouds::Settings s;
  s.densityMultiplier = 1.7f;
  const shader::CloudUniforms u = uniformsWith({}, s);
  EXPECT_EQ(u.weatherRegionCount, 0u);
  EXPECT_EQ(u.extinctionPerMetre, s.extinctionPerMetre * s.densityMultiplier);
  EXPECT_EQ(u.layerDensityScale, 1.0f);
  const shader::ColumnWeather c = shader::columnWeather(glm::vec2(1234.0f, -5.0f), u);
  EXPECT_EQ(c.coverage, s.coverage);
  EXPECT_EQ(c.cloudType, s.cloudType);
  EXPECT_EQ(c.densityScale, 1.0f);
  EXPECT_EQ(c.anvilBias, s.anvilBias);
}

TEST(WeatherRegions, FarFromTheOriginRegionsArePlacedAboutTheCamera) {
  const glm::dvec2 camera(1e7 + 0.25, -3e7);
  const shader::CloudUniforms u =
      uniformsWith({disc(camera + glm::dvec2(1500.5, -20.25), 0.0f, 1000.0f, 1.0f)}, {}, camera);
  EXPECT_EQ(u.weatherRegions[0].placement.x, 1500.5f);
  EXPECT_EQ(u.weatherRegions[0].placement.y, -20.25f);
}

TEST(WeatherRegions, HowFarRegionsMoveBetweenFrames) {
  const WeatherRegion a = disc({0.0, 0.0}, 1000.0f, 10000.0f, 0.5f);
  EXPECT_EQ(detail::weatherRegionsChange(std::vector{a}, std::vector{a}), 0.0f);
  EXPECT_EQ(detail::weatherRegionsChange(std::vector{a}, {}), 1.0f);
  WeatherRegion eased = a;
  eased.coverage += 0.005f;  // a 20 s change of 0.5 at 10 fps moves 0.0025 a frame
  EXPECT_NEAR(detail::weatherRegionsChange(std::vector{a}, std::vector{eased}), 0.005f, 1e-6f);
  WeatherRegion moved = a;
  moved.centreMetres.x += 100.0;  // 1% of its blend
  EXPECT_NEAR(detail::weatherRegionsChange(std::vector{a}, std::vector{moved}), 0.01f, 1e-6f);
  WeatherRegion denser = a;
  denser.densityMultiplier = 1.5f;  // against the larger: a third
  EXPECT_NEAR(detail::weatherRegionsChange(std::vector{a}, std::vector{denser}), 1.0f / 3.0f,
              1e-6f);
  WeatherRegion turned = a;
  turned.halfSidesMetres = {3000.0f, 4000.0f};
  WeatherRegion turnedMore = turned;
  turnedMore.headingDegrees = 1.0f;  // the far corner, 5 km out, moves 87 m
  EXPECT_NEAR(detail::weatherRegionsChange(std::vector{turned}, std::vector{turnedMore}),
              5000.0 * glm::radians(1.0) / 10000.0, 1e-5);
}

TEST(WeatherRegions, TheLookIsLedAheadOfItsChangeWithinItsRange) {
  WeatherRegion before = disc({0.0, 0.0}, 1000.0f, 1000.0f, 0.5f);
  WeatherRegion now = before;
  now.coverage = 0.51f;
  now.anvilBias = 0.99f;
  now.centreMetres.x = 10.0;  // the place is not led
  const std::vector<WeatherRegion> led =
      detail::leadRegions(std::vector{now}, std::vector{before}, 10.0f);
  ASSERT_EQ(led.size(), 1u);
  EXPECT_NEAR(led[0].coverage, 0.61f, 1e-6f);
  EXPECT_EQ(led[0].anvilBias, 1.0f);
  EXPECT_EQ(led[0].centreMetres, now.centreMetres);
  EXPECT_EQ(detail::leadRegions(std::vector{now}, {}, 10.0f)[0], now);
}

TEST(WeatherRegions, TheHistoryKeepsAnEasingRegionAndDropsAJump) {
  clouds::FrameInputs in;
  in.renderExtent = {64, 36};
  std::vector<WeatherRegion> regions = {disc({5000.0, 0.0}, 1000.0f, 5000.0f, 0.5f)};
  in.weatherRegions = regions;
  clouds::Settings s;
  s.temporalUpsampling = true;  // only a temporally upsampled history is led (temporal_state.cpp)
  detail::TemporalState temporal;
  const auto next = [&] {
    const detail::TemporalFrame f = temporal.plan(in, s, {32, 18});
    temporal.commit(f, in, s, {32, 18});
    return f;
  };
  next();
  EXPECT_TRUE(next().useHistory);
  regions[0].coverage += 0.005f;
  const detail::TemporalFrame easing = temporal.plan(in, s, {32, 18});
  EXPECT_TRUE(easing.useHistory);
  EXPECT_TRUE(easing.cloudsChanging);
  // Marched ahead of the change, as the settings are.
  EXPECT_GT(temporal.marchedRegions(in, easing)[0].coverage, regions[0].coverage);
  temporal.commit(easing, in, s, {32, 18});
  regions[0].coverage += 0.2f;
  const detail::TemporalFrame jumped = next();
  EXPECT_FALSE(jumped.useHistory);
  EXPECT_STREQ(jumped.resetReason, "weather regions changed");
}

TEST(WeatherRegions, TheColumnQueryReadsTheRegions) {
  clouds::Settings s;
  s.coverage = 0.0f;
  WeatherRegion storm = clouds::withWeather(disc({20000.0, 20000.0}, 3000.0f, 1000.0f, 0.0f),
                                            clouds::weatherPreset(clouds::WeatherPreset::Stormy));
  const std::vector<WeatherRegion> regions{storm};
  const clouds::WeatherColumn inside =
      clouds::proceduralWeatherAt(s, 3, {20000.0, 20000.0}, 0.0, regions);
  const clouds::WeatherColumn outside =
      clouds::proceduralWeatherAt(s, 3, {20000.0, 30000.0}, 0.0, regions);
  const clouds::WeatherColumn alone = clouds::proceduralWeatherAt(s, 3, {20000.0, 20000.0}, 0.0);
  EXPECT_EQ(outside.coverage, 0.0f);
  EXPECT_EQ(alone.coverage, 0.0f);
  EXPECT_GT(inside.coverage, 0.0f);
  EXPECT_EQ(inside.density, alone.density);  // the map's wetness is the map's
  EXPECT_FLOAT_EQ(inside.densityMultiplier, storm.densityMultiplier);
  EXPECT_FLOAT_EQ(outside.densityMultiplier, s.densityMultiplier);
}

// The generator's regional map: inside a region's core a texel reads as under the region's
// state, beyond its blend as under the weather around it.
TEST(WeatherRegions, TheMarchedMapIsTheRegionsStateInsideAndTheSurroundingsOutside) {
  const clouds::Settings sparse =
      clouds::withWeather(clouds::Settings{}, clouds::weatherPreset(clouds::WeatherPreset::Sparse));
  const clouds::WeatherState stormy = clouds::weatherPreset(clouds::WeatherPreset::Stormy);
  const std::vector<WeatherRegion> regions{
      clouds::withWeather(disc({25000.0, 20000.0}, 4000.0f, 3000.0f, 0.0f), stormy)};
  for (const glm::vec4 texel :
       {glm::vec4(0.4f, 0.6f, 0.8f, 1.0f), glm::vec4(0.9f, 0.2f, 0.5f, 1.0f)}) {
    EXPECT_EQ(clouds::weatherAsMarched(texel, sparse, regions, {27000.0, 21000.0}),
              clouds::weatherAsMarched(texel, clouds::withWeather(sparse, stormy)));
    EXPECT_EQ(clouds::weatherAsMarched(texel, sparse, regions, {25000.0, 28000.0}),
              clouds::weatherAsMarched(texel, sparse));
  }
}

}  // namespace
