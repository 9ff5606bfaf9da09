// The superstorm as plain logic (cloud_vortex.h, WeatherRegion::vortex): the rate it turns at
// over distance, the direction of the turn, the flow phases' clocks after any uptime, its look
// (a clear eye, a full wall, bands; the cell ceiling over it: weather_regions_test.cpp), and
// the history (nothing stands still in a turning storm; a storm appearing drops the history).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "cloud_temporal.h"
#include "cloud_weather_regions.h"
#include "clouds/clouds.h"
#include "temporal_state.h"
#include "uniforms.h"
#include "weather_regions.h"

namespace {

using clouds::WeatherRegion;
namespace shader = clouds::shader;
namespace detail = clouds::detail;

// A superstorm centred at `centre` (x, z): eye 3 km, wall 4 km (its middle 5 km out), a
// 30 km core eased out over 10 km, turning at 40 m/s at the wall.
WeatherRegion storm(glm::dvec2 centre = {0.0, 0.0}) {
  WeatherRegion r;
  r.centreMetres = centre;
  r.radiusMetres = 30000.0f;
  r.blendMetres = 10000.0f;
  r.coverage = 0.6f;
  r.cloudType = 0.8f;
  r.vortex.eyeRadiusMetres = 3000.0f;
  r.vortex.eyeWallMetres = 4000.0f;
  r.vortex.wallSpeedMetresPerSecond = 40.0f;
  r.vortex.spiralArms = 3.0f;
  return r;
}

shader::CloudUniforms uniformsWith(std::vector<WeatherRegion> regions, double seconds = 0.0,
                                   glm::dvec2 camera = {}) {
  clouds::FrameInputs in;
  in.cameraPosition = {camera.x, 500.0, camera.y};
  in.weatherRegions = regions;
  in.timeSeconds = seconds;
  clouds::Settings s;
  s.weatherRegions = 1;
  s.superstorms = 1;
  return detail::buildUniforms(in, s, detail::UniformContext{});
}

TEST(Vortex, ItTurnsAsASolidBodyToTheWallAndSlowerBeyondFadingWithItsRegion) {
  const shader::CloudUniforms u = uniformsWith({storm()});
  ASSERT_EQ(u.vortexRegion, 0u);
  const shader::WeatherRegionUniform r = u.weatherRegions[0];
  const float atWall = shader::vortexTurnRate(5000.0f, r);
  EXPECT_NEAR(atWall, 40.0f / 5000.0f, 1e-7f);                  // the wall's speed over its radius
  EXPECT_FLOAT_EQ(shader::vortexTurnRate(1000.0f, r), atWall);  // the eye turns with it
  // Beyond: the rate falls as r^-1.5 (the speed as 1/sqrt(r)).
  EXPECT_NEAR(shader::vortexTurnRate(20000.0f, r), atWall * std::pow(0.25f, 1.5f), 1e-8f);
  // Eased out with the region (smoothstep from its radius over its blend), still beyond.
  EXPECT_LT(shader::vortexTurnRate(35000.0f, r),
            atWall * std::pow(5000.0f / 35000.0f, 1.5f) * 0.51f);
  EXPECT_EQ(shader::vortexTurnRate(40001.0f, r), 0.0f);
}

TEST(Vortex, ItTurnsCounterClockwiseSeenFromAboveAndKeepsTheDistanceToTheEye) {
  const shader::CloudUniforms u = uniformsWith({storm({2000.0, -1000.0})}, 0.0, {2000.0, -1000.0});
  const shader::WeatherRegionUniform r = u.weatherRegions[0];
  // Counter-clockwise seen from above turns +x towards -z.
  const glm::vec2 quarter = shader::turnedCounterClockwise(glm::vec2(1.0f, 0.0f), 1.5707963f);
  EXPECT_NEAR(quarter.x, 0.0f, 1e-6f);
  EXPECT_NEAR(quarter.y, -1.0f, 1e-6f);
  // The cloud east of the eye (+x) came from the south (+z) of where it is: turned back.
  const glm::vec2 here(5000.0f, 0.0f);
  const float seconds = 30.0f;
  const glm::vec2 before = shader::vortexTurnedBack(here, seconds, r);
  EXPECT_NEAR(glm::length(before), 5000.0f, 0.01f);
  EXPECT_GT(before.y, 0.0f);
  EXPECT_NEAR(std::atan2(before.y, before.x), 40.0f / 5000.0f * seconds, 1e-5f);
  // Clockwise storms turn the other way.
  WeatherRegion clockwise = storm({2000.0, -1000.0});
  clockwise.vortex.wallSpeedMetresPerSecond = -40.0f;
  const shader::CloudUniforms v = uniformsWith({clockwise}, 0.0, {2000.0, -1000.0});
  EXPECT_LT(shader::vortexTurnedBack(here, seconds, v.weatherRegions[0]).y, 0.0f);
}

TEST(Vortex, ThePhasesClocksStayUnderThePeriodAfterAnyUptimeAndTheirWeightsSumToOne) {
  const WeatherRegion s = storm();
  const double period = 0.5 * 3.14159265358979 / (40.0 / 5000.0);  // a quarter of the wall's turn
  for (double t : {0.0, 1.0, 0.25 * period, 0.5 * period, 0.99 * period, 1e6, 1e6 + 0.5}) {
    const glm::vec4 c = detail::vortexClock(s, t);
    EXPECT_GE(c.x, 0.0f) << t;
    EXPECT_LT(c.x, float(period) * 1.0001f) << t;
    EXPECT_GE(c.y, 0.0f) << t;
    EXPECT_LT(c.y, float(period) * 1.0001f) << t;
    EXPECT_NEAR(std::abs(c.x - c.y), 0.5 * period, 1e-2 * period) << t;
    EXPECT_GE(c.z, 0.0f);
    EXPECT_LE(c.z, 1.0f);
    EXPECT_EQ(c.w, 0.0f);
  }
  // A phase restarts (its clock back to 0) only at no weight, so the cross-fade never pops.
  // (Either side of the restart: its clock is 0 or the period, its weight 0.)
  const auto restarting = [&](float clock) {
    return std::min(clock, float(period) - clock) < 1e-2f;
  };
  const glm::vec4 restart = detail::vortexClock(s, period);
  EXPECT_TRUE(restarting(restart.x)) << restart.x;
  EXPECT_NEAR(restart.z, 0.0f, 1e-5f);
  const glm::vec4 half = detail::vortexClock(s, 1.5 * period);
  EXPECT_TRUE(restarting(half.y)) << half.y;
  EXPECT_NEAR(half.z, 1.0f, 1e-5f);  // the second phase's weight 1 - z is 0 at its restart
  // Frame to frame the weight moves by at most 2 dt / period.
  for (double t = 0.0; t < 2.0 * period; t += 1.0 / 30.0) {
    EXPECT_LE(std::abs(detail::vortexClock(s, t + 1.0 / 30.0).z - detail::vortexClock(s, t).z),
              2.0 / 30.0 / period + 1e-6);
  }
}

TEST(Vortex, ItsEyeIsClearItsWallFullAndItsBandsWindAround) {
  WeatherRegion r = storm();
  const shader::CloudUniforms u = uniformsWith({r});
  const auto at = [&](float x, float z) { return shader::columnWeather(glm::vec2(x, z), u); };
  EXPECT_EQ(at(0.0f, 0.0f).coverage, 0.0f);  // the eye (no NaN at its centre)
  EXPECT_EQ(at(1500.0f, -1000.0f).coverage, 0.0f);
  EXPECT_FLOAT_EQ(at(5000.0f, 0.0f).coverage, 0.8f);  // the wall's middle
  EXPECT_FLOAT_EQ(at(0.0f, 5000.0f).cloudType, 1.0f);
  // Around a circle 12 km out the bands come and go (three arms: three maxima), between 30%
  // of the region's coverage and all of it.
  std::vector<float> around;
  for (int i = 0; i < 720; ++i) {
    const float a = float(i) * 6.2831853f / 720.0f;
    around.push_back(at(12000.0f * std::cos(a), -12000.0f * std::sin(a)).coverage);
  }
  int maxima = 0;
  for (std::size_t i = 0; i < around.size(); ++i) {
    const float before = around[(i + around.size() - 1) % around.size()];
    const float after = around[(i + 1) % around.size()];
    maxima += around[i] > before && around[i] >= after;
  }
  EXPECT_NEAR(*std::min_element(around.begin(), around.end()), 0.3f * r.coverage, 0.01f);
  EXPECT_NEAR(*std::max_element(around.begin(), around.end()), r.coverage, 0.01f);
  EXPECT_EQ(maxima, 3);
  // No arms: a plain ring of the region's coverage.
  r.vortex.spiralArms = 0.0f;
  const shader::CloudUniforms ring = uniformsWith({r});
  EXPECT_FLOAT_EQ(shader::columnWeather(glm::vec2(0.0f, 12000.0f), ring).coverage, r.coverage);
  EXPECT_FLOAT_EQ(shader::columnWeather(glm::vec2(12000.0f, 0.0f), ring).coverage, r.coverage);
  // The host's query reads the look as the storm's turn holds it: at a later time the same
  // column reads otherwise (the march reads it turned too: Superstorm.* on the GPU).
  const auto queried = [&](double seconds) {
    clouds::Settings s;
    s.weatherRegions = 1;
    s.superstorms = 1;
    const std::vector<WeatherRegion> regions = {storm()};
    return clouds::proceduralWeatherAt(s, 1, {12000.0, 0.0}, seconds, regions).coverage;
  };
  EXPECT_NE(queried(0.0), queried(120.0));
}

TEST(Vortex, ATurningStormNeverStandsStillAndOneAppearingDropsTheHistory) {
  clouds::FrameInputs in;
  in.renderExtent = {64, 36};
  std::vector<WeatherRegion> regions = {storm({5000.0, 0.0})};
  regions[0].vortex.eyeRadiusMetres = 0.0f;  // a plain region first
  in.weatherRegions = regions;
  clouds::Settings s;
  s.weatherRegions = 1;
  s.superstorms = 1;
  s.windSpeedMetresPerSecond = 0.0f;
  detail::TemporalState temporal;
  const auto next = [&] {
    const detail::TemporalFrame f = temporal.plan(in, s, {32, 18});
    temporal.commit(f, in, s, {32, 18});
    return f;
  };
  next();
  in.timeSeconds += 1.0 / 30.0;
  EXPECT_TRUE(next().still) << "no wind and no storm: the clouds stand still";
  regions[0].vortex.eyeRadiusMetres = 3000.0f;
  in.timeSeconds += 1.0 / 30.0;
  const detail::TemporalFrame appeared = next();
  EXPECT_FALSE(appeared.useHistory);
  EXPECT_STREQ(appeared.resetReason, "weather regions changed");
  in.timeSeconds += 1.0 / 30.0;
  const detail::TemporalFrame turning = next();
  EXPECT_TRUE(turning.useHistory);
  EXPECT_FALSE(turning.still) << "the storm turned its clouds since";
  EXPECT_NEAR(turning.secondsSinceHistory, 1.0 / 30.0, 1e-9);
  // The reprojection turns points back by the interval; with vortexReprojection off, not at all.
  detail::UniformContext context;
  context.temporal = turning;
  EXPECT_NEAR(detail::buildUniforms(in, s, context).vortexHistorySeconds, 1.0 / 30.0, 1e-6);
  s.vortexReprojection = false;
  EXPECT_EQ(detail::buildUniforms(in, s, context).vortexHistorySeconds, 0.0f);
  // A storm that speeds up by more than 1% at once drops it too.
  s.vortexReprojection = true;
  regions[0].vortex.wallSpeedMetresPerSecond *= 1.5f;
  in.timeSeconds += 1.0 / 30.0;
  EXPECT_STREQ(next().resetReason, "weather regions changed");
}

// The reprojection end to end (cloud_temporal.h, as the passes run it): a cloud point seen
// now is looked for where the storm's turn brought it from, through last frame's camera.
TEST(Vortex, TheHistoryLooksWhereTheTurnBroughtAPointFrom) {
  clouds::FrameInputs in;
  in.renderExtent = {160, 90};
  in.cameraPosition = {0.0, 7000.0, 16000.0};
  in.view = glm::lookAt(glm::vec3(in.cameraPosition), glm::vec3(0.0f, 2000.0f, 0.0f),
                        glm::vec3(0.0f, 1.0f, 0.0f));
  in.projection = glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 10.0f, 1e6f);
  std::vector<WeatherRegion> regions = {storm()};
  in.weatherRegions = regions;
  in.timeSeconds = 100.0;
  clouds::Settings s;
  s.weatherRegions = 1;
  s.superstorms = 1;
  s.windSpeedMetresPerSecond = 0.0f;
  detail::TemporalState temporal;
  const VkExtent2D trace{160, 90};
  temporal.commit(temporal.plan(in, s, trace), in, s, trace);
  in.timeSeconds = 110.0;
  detail::UniformContext context;
  context.temporal = temporal.plan(in, s, trace);
  ASSERT_TRUE(context.temporal.useHistory);
  const glm::vec3 point(6000.0f, 2500.0f, 1500.0f);  // on the wall, 6.2 km from the eye
  const glm::vec3 relative = point - glm::vec3(in.cameraPosition);
  const glm::vec3 direction = glm::normalize(glm::mat3(in.view) * relative);
  const float distance = glm::length(relative);
  const glm::vec2 extent(160.0f, 90.0f);
  const auto pixelOf = [&](glm::vec3 world) {  // through the (unmoved) camera
    const glm::vec4 clip = in.projection * in.view * glm::vec4(world, 1.0f);
    return (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * extent;
  };
  const shader::CloudUniforms u = detail::buildUniforms(in, s, context);
  const glm::vec2 found =
      shader::reprojectPixel(direction, glm::vec2(distance), extent, u).position;
  const glm::vec2 before =
      shader::vortexTurnedBack(glm::vec2(point.x, point.z) - glm::vec2(0.0f, 16000.0f), 10.0f,
                               u.weatherRegions[0]) +
      glm::vec2(0.0f, 16000.0f);
  const glm::vec2 expected = pixelOf(glm::vec3(before.x, point.y, before.y));
  EXPECT_NEAR(found.x, expected.x, 0.02f);
  EXPECT_NEAR(found.y, expected.y, 0.02f);
  EXPECT_GT(glm::length(expected - pixelOf(point)), 0.3f) << "the storm moved it";
  // Plain: where the point itself was.
  s.vortexReprojection = false;
  const glm::vec2 plain = shader::reprojectPixel(direction, glm::vec2(distance), extent,
                                                 detail::buildUniforms(in, s, context))
                              .position;
  EXPECT_NEAR(plain.x, pixelOf(point).x, 0.02f);
  EXPECT_NEAR(plain.y, pixelOf(point).y, 0.02f);
}

TEST(Vortex, WithoutAStormTheUniformsHoldNone) {
  WeatherRegion plain = storm();
  plain.vortex.eyeRadiusMetres = 0.0f;
  const shader::CloudUniforms u = uniformsWith({plain}, 500.0);
  EXPECT_EQ(u.vortexRegion, shader::kNoVortex);
  EXPECT_EQ(u.weatherRegions[0].vortex, glm::vec4(0.0f));
  EXPECT_EQ(u.vortexClock, glm::vec4(0.0f));
}

TEST(Vortex, OneStormAtMost) {
  clouds::Settings s;
  s.weatherRegions = 1;
  s.superstorms = 1;
  EXPECT_EQ(clouds::validateSettings(s), "");
  s.superstorms = 2;
  EXPECT_NE(clouds::validateSettings(s).find("Settings.superstorms"), std::string::npos);
}

}  // namespace
