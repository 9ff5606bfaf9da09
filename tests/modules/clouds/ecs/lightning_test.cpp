// Lightning as ECS data, without a GPU: strikes are a pure function of the storm's seed and the
// clock (the same at any frame rate, different for another seed, at the storm's rate), a
// strike's return strokes light it and then it is dark, the "lightning" system sends an event
// per strike (each once, at any step and uptime; none while the clock is paused, which holds
// the flashes) and keeps the ones in progress, a trigger strikes at once, the clouds' inputs get
// the brightest flashes and the whole bolts there is room for, a ground strike's bolt is a
// branching channel to the ground, and a scene without a storm has no system.
#include <gtest/gtest.h>

#include <cmath>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/cloud_frame.h"
#include "clouds/ecs/lightning.h"
#include "engine/ecs/events.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"

namespace {

using clouds::ecs::LightningStorm;
using clouds::ecs::LightningStrike;

LightningStorm storm(std::uint32_t seed = 7) {
  LightningStorm s;
  s.cells = {{{0.0, 3000.0, 0.0}, 5000.0f}, {{8000.0, 3000.0, 0.0}, 5000.0f}};
  s.strikesPerMinute = 6.0;
  s.seed = seed;
  return s;
}

TEST(Lightning, StrikesAreTheSameAtAnyFrameRate) {
  const LightningStorm s = storm();
  const std::vector<LightningStrike> once = clouds::ecs::strikesBetween(s, 0.0, 600.0);
  for (const double dt : {1.0 / 30.0, 1.0 / 144.0, 0.25}) {
    std::vector<LightningStrike> framed;
    for (double t = 0.0; t < 600.0; t += dt) {
      const auto part = clouds::ecs::strikesBetween(s, t, std::min(t + dt, 600.0));
      framed.insert(framed.end(), part.begin(), part.end());
    }
    ASSERT_EQ(framed.size(), once.size()) << "dt " << dt;
    for (std::size_t i = 0; i < once.size(); ++i) {
      EXPECT_EQ(framed[i].startSeconds, once[i].startSeconds);
      EXPECT_EQ(framed[i].positionMetres, once[i].positionMetres);
      EXPECT_EQ(framed[i].energy, once[i].energy);
    }
  }
}

TEST(Lightning, StrikesFollowTheRateAndTheSeed) {
  const auto hour = clouds::ecs::strikesBetween(storm(), 0.0, 3600.0);
  // Two cells at 6 a minute for an hour: 720 expected (a Poisson count, sd 27).
  EXPECT_NEAR(double(hour.size()), 720.0, 100.0);
  std::size_t ground = 0;
  for (const LightningStrike& s : hour) {
    if (s.kind == clouds::ecs::StrikeKind::Ground) ++ground;
    EXPECT_TRUE(s.strokes == 3 || s.strokes == 4);
    EXPECT_GE(s.durationSeconds, 0.2);
    EXPECT_LE(s.durationSeconds, 0.5);
  }
  EXPECT_NEAR(double(ground) / double(hour.size()), 0.3, 0.08);
  const auto other = clouds::ecs::strikesBetween(storm(8), 0.0, 3600.0);
  ASSERT_FALSE(other.empty());
  EXPECT_NE(other.front().startSeconds, hour.front().startSeconds) << "another seed";
  LightningStorm calm = storm();
  calm.strikesPerMinute = 0.0;
  EXPECT_TRUE(clouds::ecs::strikesBetween(calm, 0.0, 3600.0).empty());
  EXPECT_TRUE(clouds::ecs::strikesBetween(storm(), 5.0, 5.0).empty());
  EXPECT_TRUE(clouds::ecs::strikesBetween(storm(), std::nan(""), 5.0).empty());
}

TEST(Lightning, ReturnStrokesLightAStrikeThenItIsDark) {
  LightningStrike s;
  s.startSeconds = 10.0;
  s.durationSeconds = 0.3;
  s.strokes = 3;
  EXPECT_EQ(clouds::ecs::strikeEnvelope(s, 9.99), 0.0f);
  EXPECT_FLOAT_EQ(clouds::ecs::strikeEnvelope(s, 10.0), 1.0f);
  // Each stroke brightens the fading flash again, 50 ms apart.
  EXPECT_GT(clouds::ecs::strikeEnvelope(s, 10.0501), clouds::ecs::strikeEnvelope(s, 10.049));
  EXPECT_GT(clouds::ecs::strikeEnvelope(s, 10.1001), clouds::ecs::strikeEnvelope(s, 10.099));
  EXPECT_LT(clouds::ecs::strikeEnvelope(s, 10.25), 0.05f);
  EXPECT_EQ(clouds::ecs::strikeEnvelope(s, 10.31), 0.0f);
  for (double t = 9.9; t < 10.4; t += 0.001) {
    const float e = clouds::ecs::strikeEnvelope(s, t);
    ASSERT_TRUE(e >= 0.0f && e <= 1.0f) << t;
  }
}

struct StormWorld {
  engine::ecs::World world;
  engine::ecs::Scheduler scheduler;
  engine::ecs::Entity stormEntity;
  StormWorld() {
    world.ctx().emplace<engine::ecs::FrameTime>();
    world.emplace<clouds::ecs::CloudLayer>(world.create(), clouds::ecs::CloudLayer{});
    LightningStorm s = storm();
    s.strikesPerMinute = 60.0;
    stormEntity = world.create();
    world.emplace<LightningStorm>(stormEntity, s);
  }
  void frame(double dt) {
    auto& time = world.ctx().get<engine::ecs::FrameTime>();
    time = time.next(dt);
    scheduler.runFrame(world);
  }
  // The first frame, its clock at `seconds` (the uptime).
  void firstFrame(double seconds) {
    world.ctx().get<engine::ecs::FrameTime>() = engine::ecs::FrameTime{0.0, seconds, 0};
    scheduler.runFrame(world);
  }
  // The strikes sent since the last call.
  std::vector<LightningStrike> sent() {
    const auto unread = reader.read(world.events<LightningStrike>());
    return {unread.begin(), unread.end()};
  }
  engine::ecs::EventReader<LightningStrike> reader;
};

// The strikes a run of frames sends are exactly the storm's strikes over the time it covered:
// none lost or sent twice at a frame boundary, whatever the steps (here 0, 1/144 s, 1/30 s and
// 10 s, and a frame ending at a strike's start), after an uptime of 0 or 1e6 s.
TEST(Lightning, TheSystemSendsEachStrikeOnceAtAnyStepAndUptime) {
  for (const double uptime : {0.0, 1e6}) {
    StormWorld w;
    ASSERT_TRUE(clouds::ecs::installLightning(w.world, w.scheduler));
    const LightningStorm s = w.world.get<LightningStorm>(w.stormEntity);
    const double firstStrike =
        clouds::ecs::strikesBetween(s, uptime, uptime + 60.0).at(0).startSeconds;
    std::vector<LightningStrike> sent;
    auto collect = [&] {
      for (const LightningStrike& strike : w.sent()) sent.push_back(strike);
    };
    w.firstFrame(uptime);
    collect();
    w.frame(firstStrike - uptime);  // ends at the first strike's start
    collect();
    const double steps[] = {0.0, 1.0 / 144.0, 1.0 / 30.0, 0.0, 10.0, 1.0 / 30.0};
    for (int i = 0; i < 600; ++i) {
      w.frame(steps[i % 6]);
      collect();
    }
    const double end = w.world.ctx().get<engine::ecs::FrameTime>().elapsedSeconds;
    const std::vector<LightningStrike> expected = clouds::ecs::strikesBetween(s, uptime, end);
    ASSERT_GT(expected.size(), 400u) << "two cells at 60 a minute for 17 minutes";
    ASSERT_EQ(sent.size(), expected.size()) << "uptime " << uptime;
    for (std::size_t i = 0; i < sent.size(); ++i) {
      ASSERT_EQ(sent[i].startSeconds, expected[i].startSeconds) << "uptime " << uptime;
    }
  }
}

// Changing weather sets the rate: a storm strikes only while the state strikes (Sparse for a
// minute, then 20 s into Stormy), as deterministically at any frame rate; the system follows it.
// A region of stormy weather strikes where it lies: of two cells 8 km apart under fair skies,
// only the one in the region strikes, and it starts when the region's own schedule turns stormy.
TEST(Lightning, OnlyTheCellsInAStormRegionStrike) {
  const clouds::WeatherKey fair[] = {
      {clouds::weatherPreset(clouds::WeatherPreset::Sparse), 60.0, 0.0}};
  const clouds::WeatherKey building[] = {
      {clouds::weatherPreset(clouds::WeatherPreset::Cloudy), 100.0, 20.0},
      {clouds::weatherPreset(clouds::WeatherPreset::Stormy), 600.0, 0.0}};
  clouds::WeatherRegion place;
  place.centreMetres = {8000.0, 0.0};  // over the second cell
  place.radiusMetres = 2000.0f;
  place.blendMetres = 3000.0f;
  clouds::ecs::CloudWeather weather{*clouds::WeatherTimeline::schedule(fair, false, nullptr)};
  weather.regions.push_back(
      {"front", place, *clouds::WeatherTimeline::schedule(building, false, nullptr)});
  const auto strikes = clouds::ecs::strikesBetween(storm(), 0.0, 600.0, &weather);
  ASSERT_GT(strikes.size(), 10u);
  for (const LightningStrike& strike : strikes) {
    EXPECT_EQ(strike.positionMetres.x, 8000.0) << "a strike under fair skies";
    EXPECT_GT(strike.startSeconds, 100.0) << "a strike before the region's storm";
  }
  // Its state over each cell: the region's over the second, the fair sky's over the first.
  EXPECT_EQ(weather.stateAt(200.0, {8000.0, 0.0}).lightningStrikesPerMinute,
            clouds::weatherPreset(clouds::WeatherPreset::Stormy).lightningStrikesPerMinute);
  EXPECT_EQ(weather.stateAt(200.0, {0.0, 0.0}), weather.timeline.stateAt(200.0));
}

TEST(Lightning, AStormStrikesWithTheWeather) {
  const clouds::WeatherKey keys[] = {
      {clouds::weatherPreset(clouds::WeatherPreset::Sparse), 60.0, 20.0},
      {clouds::weatherPreset(clouds::WeatherPreset::Stormy), 120.0, 20.0}};
  const clouds::ecs::CloudWeather weather{*clouds::WeatherTimeline::schedule(keys, true, nullptr)};
  const LightningStorm s = storm();
  const auto strikes = clouds::ecs::strikesBetween(s, 0.0, 440.0, &weather);
  ASSERT_GT(strikes.size(), 10u);
  for (const LightningStrike& strike : strikes) {
    const double inCycle = std::fmod(strike.startSeconds, 220.0);
    EXPECT_GT(inCycle, 60.0) << "no strike while it is sparse";
    EXPECT_LT(inCycle, 220.0);
  }
  std::vector<LightningStrike> framed;
  for (double t = 0.0; t < 440.0; t += 1.0 / 30.0) {
    const auto part = clouds::ecs::strikesBetween(s, t, std::min(t + 1.0 / 30.0, 440.0), &weather);
    framed.insert(framed.end(), part.begin(), part.end());
  }
  ASSERT_EQ(framed.size(), strikes.size());
  // The system takes the layer's weather.
  StormWorld w;
  w.world.view<clouds::ecs::CloudLayer>().each(
      [&](engine::ecs::Entity layer, clouds::ecs::CloudLayer&) {
        w.world.emplace<clouds::ecs::CloudWeather>(layer, weather);
      });
  ASSERT_TRUE(clouds::ecs::installLightning(w.world, w.scheduler));
  w.firstFrame(0.0);
  std::size_t sent = w.sent().size();
  for (int i = 0; i < 30 * 60; ++i) {
    w.frame(1.0 / 30.0);
    sent += w.sent().size();
  }
  EXPECT_EQ(sent, 0u) << "a minute of sparse weather";
  for (int i = 0; i < 30 * 60; ++i) {
    w.frame(1.0 / 30.0);
    sent += w.sent().size();
  }
  EXPECT_GT(sent, 20u) << "two cells at the storm's 12 a minute";
}

// A paused clock (steps of 0) sends no strike, not even one starting at that very moment (once
// it runs again, that one is sent once), and holds the strikes in progress and their flashes.
TEST(Lightning, APausedClockHoldsTheStrikesAndTheirFlashes) {
  StormWorld w;
  ASSERT_TRUE(clouds::ecs::installLightning(w.world, w.scheduler));
  const LightningStorm s = w.world.get<LightningStorm>(w.stormEntity);
  const double strikeStart = clouds::ecs::strikesBetween(s, 0.0, 60.0).at(0).startSeconds;
  w.firstFrame(strikeStart);
  std::size_t sent = w.sent().size();
  for (int i = 0; i < 50; ++i) {
    w.frame(0.0);
    sent += w.sent().size();
  }
  w.frame(0.02);
  sent += w.sent().size();
  EXPECT_EQ(sent, 1u) << "the strike starting when the clock stopped";
  const auto flashes = clouds::ecs::lightningFlashes(w.world, 8);
  ASSERT_FALSE(flashes.empty());
  for (int i = 0; i < 100; ++i) {
    w.frame(0.0);
    ASSERT_TRUE(w.sent().empty()) << "paused frame " << i;
    const auto held = clouds::ecs::lightningFlashes(w.world, 8);
    ASSERT_EQ(held.size(), flashes.size());
    for (std::size_t f = 0; f < held.size(); ++f) ASSERT_EQ(held[f].radiance, flashes[f].radiance);
  }
}

// A host that sets its clock back (a new session at 0 after 10 minutes) gets strikes again from
// its first step, not after the old clock's time has passed once more.
TEST(Lightning, AClockSetBackStrikesFromItsNextStep) {
  StormWorld w;
  ASSERT_TRUE(clouds::ecs::installLightning(w.world, w.scheduler));
  w.firstFrame(600.0);
  w.frame(1.0);
  w.sent();
  w.firstFrame(0.0);
  std::size_t sent = 0;
  for (int i = 0; i < 60; ++i) {
    w.frame(1.0);
    sent += w.sent().size();
  }
  const LightningStorm s = w.world.get<LightningStorm>(w.stormEntity);
  EXPECT_EQ(sent, clouds::ecs::strikesBetween(s, 0.0, 60.0).size());
  EXPECT_GT(sent, 0u);
}

TEST(Lightning, TheSystemSendsAnEventPerStrikeAndKeepsThoseInProgress) {
  StormWorld w;
  ASSERT_TRUE(clouds::ecs::installLightning(w.world, w.scheduler));
  engine::ecs::EventReader<LightningStrike> reader;
  std::size_t events = 0;
  std::size_t framesWithActive = 0;
  for (int i = 0; i < 30 * 60; ++i) {  // a minute at 30 fps
    w.frame(1.0 / 30.0);
    for (const LightningStrike& s : reader.read(w.world.events<LightningStrike>())) {
      (void)s;
      ++events;
    }
    const auto& active = w.world.ctx().get<clouds::ecs::ActiveLightning>().strikes;
    if (!active.empty()) ++framesWithActive;
    const double now = w.world.ctx().get<engine::ecs::FrameTime>().elapsedSeconds;
    for (const LightningStrike& s : active) {
      ASSERT_LE(s.startSeconds, now + 1e-9);
      ASSERT_GE(s.startSeconds + s.durationSeconds, now);
    }
  }
  // Two cells at 60 a minute: about 120 strikes, each an event.
  EXPECT_NEAR(double(events), 120.0, 40.0);
  EXPECT_GT(framesWithActive, 100u);
}

TEST(Lightning, ATriggerStrikesAtOnceAndTheCloudsGetItsFlash) {
  StormWorld w;
  w.world.get<LightningStorm>(w.stormEntity).strikesPerMinute = 0.0;
  ASSERT_TRUE(clouds::ecs::installLightning(w.world, w.scheduler));
  w.frame(1.0 / 30.0);
  EXPECT_TRUE(clouds::ecs::lightningFlashes(w.world, 8).empty()) << "a calm storm";
  w.world.events<clouds::ecs::TriggerLightning>().send(clouds::ecs::TriggerLightning{});
  w.frame(1.0 / 30.0);
  const auto flashes = clouds::ecs::lightningFlashes(w.world, 8);
  ASSERT_EQ(flashes.size(), 1u);
  EXPECT_EQ(flashes[0].positionMetres, storm().cells[0].positionMetres);
  EXPECT_GT(flashes[0].radiance.b, 0.0f);
  EXPECT_TRUE(clouds::ecs::lightningFlashes(w.world, 0).empty()) << "no room, no flash";
  for (int i = 0; i < 20; ++i) w.frame(1.0 / 30.0);
  EXPECT_TRUE(clouds::ecs::lightningFlashes(w.world, 8).empty()) << "over after 0.5 s";
  EXPECT_EQ(clouds::ecs::cloudSettings(w.world).lightningFlashes, clouds::ecs::kLightningFlashes);
}

// A hundred strikes at once: the clouds get the brightest there is room for, all finite.
TEST(Lightning, AHundredStrikesAtOnceGiveTheBrightestFlashes) {
  StormWorld w;
  w.world.get<LightningStorm>(w.stormEntity).strikesPerMinute = 0.0;
  ASSERT_TRUE(clouds::ecs::installLightning(w.world, w.scheduler));
  for (int i = 0; i < 100; ++i) {
    w.world.events<clouds::ecs::TriggerLightning>().send(
        clouds::ecs::TriggerLightning{float(i) * 0.01f, clouds::ecs::StrikeKind::Ground});
  }
  w.frame(1.0 / 30.0);
  EXPECT_EQ(w.world.ctx().get<clouds::ecs::ActiveLightning>().strikes.size(), 100u);
  const auto flashes = clouds::ecs::lightningFlashes(w.world, clouds::ecs::kLightningFlashes);
  ASSERT_EQ(flashes.size(), clouds::ecs::kLightningFlashes);
  for (std::size_t i = 0; i < flashes.size(); ++i) {
    EXPECT_TRUE(std::isfinite(flashes[i].radiance.b));
    if (i > 0) {
      EXPECT_LE(flashes[i].radiance.b, flashes[i - 1].radiance.b);
    }
  }
  // The brightest: the last of the hundred (energy 0.99).
  EXPECT_NEAR(flashes[0].radiance.b, 0.99f * storm().radiance, 1e-3f * storm().radiance);
}

TEST(Lightning, NoStormNoSystemNoRoom) {
  engine::ecs::World world;
  engine::ecs::Scheduler scheduler;
  world.ctx().emplace<engine::ecs::FrameTime>();
  world.emplace<clouds::ecs::CloudLayer>(world.create(), clouds::ecs::CloudLayer{});
  EXPECT_FALSE(clouds::ecs::installLightning(world, scheduler));
  EXPECT_FALSE(world.ctx().has<clouds::ecs::ActiveLightning>());
  EXPECT_EQ(clouds::ecs::cloudSettings(world).lightningFlashes, 0u);
  EXPECT_EQ(clouds::ecs::cloudSettings(world).lightningBoltSegments, 0u);
  EXPECT_TRUE(clouds::ecs::lightningFlashes(world, 8).empty());
  EXPECT_TRUE(clouds::ecs::lightningBolts(world, 128).empty());
}

// A ground discharge's bolt: a pure function of the strike, a connected channel from its
// charge to the ground with dimmer branches off it; nothing for an intra-cloud strike.
TEST(Lightning, AGroundStrikeDrawsABranchingBoltToTheGround) {
  LightningStrike strike;
  strike.kind = clouds::ecs::StrikeKind::Ground;
  strike.positionMetres = {1000.0, 2500.0, -3000.0};
  strike.groundAltitudeMetres = 150.0;
  strike.seed = 42;
  const auto bolt = clouds::ecs::boltSegments(strike, 1.0f);
  ASSERT_FALSE(bolt.empty());
  ASSERT_LE(bolt.size(), std::size_t{clouds::ecs::kBoltSegments});
  EXPECT_EQ(bolt.front().fromMetres, strike.positionMetres) << "from the charge";
  // The channel: pieces end to end down to the ground, the brightest.
  std::size_t channel = 1;
  while (channel < bolt.size() && bolt[channel].fromMetres == bolt[channel - 1].toMetres) {
    ++channel;
  }
  EXPECT_GE(channel, 16u);
  EXPECT_EQ(bolt[channel - 1].toMetres.y, 150.0) << "to the ground";
  const glm::dvec3 offset = bolt[channel - 1].toMetres - strike.positionMetres;
  EXPECT_LE(std::hypot(offset.x, offset.z), 0.25 * 2350.0 * std::sqrt(2.0));
  EXPECT_GT(bolt.size(), channel) << "branches";
  for (std::size_t i = channel; i < bolt.size(); ++i) {
    EXPECT_LT(bolt[i].radiance.b, bolt[0].radiance.b) << "branches are dimmer";
    EXPECT_GT(bolt[i].widthMetres, 0.0f);
  }
  // Jagged, not straight: some piece leans away from the vertical.
  double lean = 0.0;
  for (std::size_t i = 0; i < channel; ++i) {
    const glm::dvec3 d = bolt[i].toMetres - bolt[i].fromMetres;
    lean = std::max(lean, std::hypot(d.x, d.z) / std::max(std::abs(d.y), 1e-9));
  }
  EXPECT_GT(lean, 0.3);
  // The same strike, the same bolt; another seed, another.
  const auto again = clouds::ecs::boltSegments(strike, 1.0f);
  ASSERT_EQ(again.size(), bolt.size());
  for (std::size_t i = 0; i < bolt.size(); ++i) EXPECT_EQ(again[i].toMetres, bolt[i].toMetres);
  LightningStrike other = strike;
  other.seed = 43;
  EXPECT_NE(clouds::ecs::boltSegments(other, 1.0f)[1].fromMetres, bolt[1].fromMetres);
  // Twice the brightness, twice the radiance.
  EXPECT_FLOAT_EQ(clouds::ecs::boltSegments(strike, 2.0f)[0].radiance.b, 2.0f * bolt[0].radiance.b);
  // None within the cloud only, none when dark, none from below the ground.
  LightningStrike inCloud = strike;
  inCloud.kind = clouds::ecs::StrikeKind::IntraCloud;
  EXPECT_TRUE(clouds::ecs::boltSegments(inCloud, 1.0f).empty());
  EXPECT_TRUE(clouds::ecs::boltSegments(strike, 0.0f).empty());
  LightningStrike underground = strike;
  underground.groundAltitudeMetres = 3000.0;
  EXPECT_TRUE(clouds::ecs::boltSegments(underground, 1.0f).empty());
}

// The clouds' inputs get the bolts of the ground strikes in progress, whole, as many as fit.
TEST(Lightning, TheCloudsGetWholeBoltsThatFit) {
  StormWorld w;
  w.world.get<LightningStorm>(w.stormEntity).strikesPerMinute = 0.0;
  ASSERT_TRUE(clouds::ecs::installLightning(w.world, w.scheduler));
  EXPECT_EQ(clouds::ecs::cloudSettings(w.world).lightningBoltSegments,
            clouds::ecs::kLightningBoltSegments);
  w.world.events<clouds::ecs::TriggerLightning>().send(
      clouds::ecs::TriggerLightning{1.0f, clouds::ecs::StrikeKind::IntraCloud});
  w.frame(1.0 / 30.0);
  EXPECT_TRUE(clouds::ecs::lightningBolts(w.world, 128).empty()) << "no bolt inside the cloud";
  for (int i = 0; i < 3; ++i) {
    w.world.events<clouds::ecs::TriggerLightning>().send(
        clouds::ecs::TriggerLightning{1.0f, clouds::ecs::StrikeKind::Ground});
  }
  w.frame(1.0 / 30.0);
  const std::size_t one = clouds::ecs::lightningBolts(w.world, clouds::ecs::kBoltSegments).size();
  EXPECT_GT(one, 0u);
  EXPECT_LE(one, std::size_t{clouds::ecs::kBoltSegments});
  const std::size_t all = clouds::ecs::lightningBolts(w.world, 100000).size();
  EXPECT_GT(all, one) << "three bolts";
  EXPECT_LE(clouds::ecs::lightningBolts(w.world, 128).size(), 128u);
  EXPECT_TRUE(clouds::ecs::lightningBolts(w.world, 0).empty()) << "no room, no bolt";
}

// Cells from the weather: where the procedural weather holds cumulonimbus, apart, strongest
// first, a third of the way up the layer; none where the weather has none.
TEST(Lightning, StormCellsSitWhereTheWeatherHoldsCumulonimbus) {
  clouds::Settings s;
  s.coverage = 0.55f;
  s.cloudType = 1.0f;
  s.layerBottomMetres = 1800.0f;
  s.layerTopMetres = 11000.0f;
  const glm::dvec2 centre(5000.0, -10000.0);
  const auto cells = clouds::ecs::stormCellsFromWeather(s, 12, centre, 14000.0, 3, 5000.0f);
  ASSERT_EQ(cells.size(), 3u);
  double lastStrength = 1e9;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const glm::dvec3 p = cells[i].positionMetres;
    EXPECT_NEAR(p.y, 1800.0 + 9200.0 / 3.0, 1e-6);
    EXPECT_EQ(cells[i].radiusMetres, 5000.0f);
    EXPECT_LE(std::abs(p.x - centre.x), 14000.0 + 1e-6);
    EXPECT_LE(std::abs(p.z - centre.y), 14000.0 + 1e-6);
    const clouds::WeatherColumn w = clouds::proceduralWeatherAt(s, 12, {p.x, p.z}, 0.0);
    EXPECT_GE(w.type, 0.75f);
    EXPECT_GE(w.coverage, 0.5f);
    const double strength = double(w.coverage) * w.density * (w.type - 0.5);
    EXPECT_LE(strength, lastStrength) << "strongest first";
    lastStrength = strength;
    for (std::size_t j = 0; j < i; ++j) {
      const glm::dvec3 q = cells[j].positionMetres;
      EXPECT_GE(std::hypot(p.x - q.x, p.z - q.z), 5000.0) << "cells apart";
    }
  }
  // The same weather, the same cells; another seed, others.
  EXPECT_EQ(
      clouds::ecs::stormCellsFromWeather(s, 12, centre, 14000.0, 3, 5000.0f)[0].positionMetres,
      cells[0].positionMetres);
  EXPECT_NE(
      clouds::ecs::stormCellsFromWeather(s, 13, centre, 14000.0, 3, 5000.0f)[0].positionMetres,
      cells[0].positionMetres);
  // Stratocumulus weather holds no cumulonimbus.
  s.cloudType = 0.4f;
  EXPECT_TRUE(clouds::ecs::stormCellsFromWeather(s, 12, centre, 14000.0, 3, 5000.0f).empty());
}

// A superstorm's lightning is its own: in fair weather, the cells the weather holds lie in its
// wall and bands, none in its clear eye, and its stormy state strikes there.
TEST(Lightning, ASuperstormsCellsLieInItsWallAndBandsNotItsEye) {
  clouds::Settings s =
      clouds::withWeather(clouds::Settings{}, clouds::weatherPreset(clouds::WeatherPreset::Sparse));
  s.cloudType = 0.3f;  // no cumulonimbus around the storm
  s.weatherRegions = 1;
  s.superstorms = 1;
  clouds::WeatherRegion superstorm;
  superstorm.centreMetres = {-3000.0, 4000.0};
  superstorm.radiusMetres = 20000.0f;
  superstorm.blendMetres = 6000.0f;
  superstorm =
      clouds::withWeather(superstorm, clouds::weatherPreset(clouds::WeatherPreset::Stormy));
  superstorm.vortex.eyeRadiusMetres = 4000.0f;
  superstorm.vortex.eyeWallMetres = 4500.0f;
  const std::vector<clouds::WeatherRegion> regions = {superstorm};
  EXPECT_TRUE(
      clouds::ecs::stormCellsFromWeather(s, 12, superstorm.centreMetres, 20000.0, 3, 3000.0f)
          .empty())
      << "fair weather alone holds no cumulonimbus";
  const auto cells = clouds::ecs::stormCellsFromWeather(s, 12, superstorm.centreMetres, 20000.0, 3,
                                                        3000.0f, regions);
  ASSERT_EQ(cells.size(), 3u);
  for (const clouds::ecs::LightningCell& cell : cells) {
    const double fromEye = std::hypot(cell.positionMetres.x - superstorm.centreMetres.x,
                                      cell.positionMetres.z - superstorm.centreMetres.y);
    EXPECT_GT(fromEye, 0.7 * 4000.0) << "a cell in the clear eye";
    EXPECT_LT(fromEye, 26000.0) << "a cell beyond the storm";
  }
}

}  // namespace
