#include "clouds/ecs/lightning.h"

#include <algorithm>
#include <cmath>

#include "clouds/ecs/cloud_components.h"
#include "engine/ecs/events.h"
#include "engine/ecs/frame_time.h"

namespace clouds::ecs {
namespace {

constexpr double kSlotSeconds = 0.1;
constexpr double kStrokeSpacingSeconds = 0.05;
constexpr double kStrokeDecaySeconds = 0.025;

// SplitMix64: a well-mixed hash of a counter.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// A uniform number in [0, 1) from a key and a stream index.
double uniform(std::uint64_t key, std::uint64_t stream) {
  return double(mix(key ^ mix(stream)) >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace

std::vector<LightningStrike> strikesBetween(const LightningStorm& storm, double fromSeconds,
                                            double toSeconds, const CloudWeather* weather) {
  std::vector<LightningStrike> strikes;
  if (!(toSeconds > fromSeconds) || !std::isfinite(fromSeconds) || !std::isfinite(toSeconds)) {
    return strikes;
  }
  const auto chance = [](double perMinute) {
    return std::clamp(perMinute / 60.0 * kSlotSeconds, 0.0, 1.0);
  };
  const double stormChance = chance(storm.strikesPerMinute);
  const auto first = static_cast<std::int64_t>(std::floor(fromSeconds / kSlotSeconds));
  const auto last = static_cast<std::int64_t>(std::floor(toSeconds / kSlotSeconds));
  for (std::size_t c = 0; c < storm.cells.size(); ++c) {
    const glm::dvec2 column(storm.cells[c].positionMetres.x, storm.cells[c].positionMetres.z);
    for (std::int64_t slot = first; slot <= last; ++slot) {
      const std::uint64_t key =
          mix(mix(storm.seed) ^ mix(std::uint64_t(c) + 1)) ^ std::uint64_t(slot);
      const double perSlot =
          weather
              ? chance(
                    weather->stateAt(double(slot) * kSlotSeconds, column).lightningStrikesPerMinute)
              : stormChance;
      if (uniform(key, 0) >= perSlot) continue;
      LightningStrike s;
      s.startSeconds = (double(slot) + uniform(key, 1)) * kSlotSeconds;
      if (s.startSeconds < fromSeconds || s.startSeconds >= toSeconds) continue;
      const LightningCell& cell = storm.cells[c];
      s.positionMetres = cell.positionMetres;
      s.radiusMetres = cell.radiusMetres;
      s.energy = float(0.5 + uniform(key, 2));
      s.kind = uniform(key, 3) < storm.groundFraction ? StrikeKind::Ground : StrikeKind::IntraCloud;
      s.strokes = 3u + (uniform(key, 4) < 0.5 ? 1u : 0u);
      s.durationSeconds = 0.2 + 0.3 * uniform(key, 5);
      s.radiance = storm.radiance;
      s.seed = static_cast<std::uint32_t>(mix(key ^ 6u));
      s.groundAltitudeMetres = storm.groundAltitudeMetres;
      strikes.push_back(s);
    }
  }
  std::sort(strikes.begin(), strikes.end(), [](const LightningStrike& a, const LightningStrike& b) {
    return a.startSeconds < b.startSeconds;
  });
  return strikes;
}

float strikeEnvelope(const LightningStrike& strike, double seconds) {
  const double t = seconds - strike.startSeconds;
  if (!(t >= 0.0) || t > strike.durationSeconds) return 0.0f;
  double brightness = 0.0;
  for (std::uint32_t k = 0; k < strike.strokes; ++k) {
    const double since = t - double(k) * kStrokeSpacingSeconds;
    if (since < 0.0) break;
    // Later return strokes are weaker.
    brightness += std::exp(-since / kStrokeDecaySeconds) / double(k + 1);
  }
  return float(std::clamp(brightness, 0.0, 1.0));
}

namespace {

// A bolt's channel: radiance over the flash's glow (a channel outshines the cloud it lights by
// orders of magnitude; this keeps it white at any exposure the glow reads at), its width (m),
// and a branch's share of both.
constexpr float kChannelRadiance = 100.0f;
constexpr float kChannelWidthMetres = 3.0f;
constexpr float kBranchShare = 0.35f;
constexpr std::uint32_t kMainPieces = 32;   // a power of two (midpoint displacement)
constexpr std::uint32_t kBranchPieces = 8;  // likewise
constexpr std::uint32_t kBranches = (kBoltSegments - kMainPieces) / kBranchPieces;

// A point in [-1, 1]^3 from a key and a stream.
glm::dvec3 jitter(std::uint64_t key, std::uint64_t stream) {
  return glm::dvec3(uniform(key, 3 * stream), uniform(key, 3 * stream + 1),
                    uniform(key, 3 * stream + 2)) *
             2.0 -
         1.0;
}

// `pieces` + 1 points from `from` to `to`, each midpoint moved sideways by up to `roughness` of
// its span (less vertically): a jagged channel.
std::vector<glm::dvec3> jaggedPath(glm::dvec3 from, glm::dvec3 to, std::uint32_t pieces,
                                   double roughness, std::uint64_t key) {
  std::vector<glm::dvec3> points(pieces + 1);
  points.front() = from;
  points.back() = to;
  for (std::uint32_t step = pieces / 2; step >= 1; step /= 2) {
    for (std::uint32_t i = step; i < pieces; i += 2 * step) {
      const glm::dvec3 a = points[i - step];
      const glm::dvec3 b = points[i + step];
      const glm::dvec3 offset = jitter(key, i) * glm::dvec3(1.0, 0.3, 1.0);
      points[i] = 0.5 * (a + b) + offset * (roughness * glm::length(b - a));
    }
  }
  return points;
}

void appendPath(const std::vector<glm::dvec3>& points, glm::vec3 radiance, float widthMetres,
                std::vector<clouds::LightningBoltSegment>& out) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    out.push_back({points[i], points[i + 1], radiance, widthMetres});
  }
}

}  // namespace

std::vector<clouds::LightningBoltSegment> boltSegments(const LightningStrike& strike,
                                                       float brightness) {
  std::vector<clouds::LightningBoltSegment> segments;
  if (strike.kind != StrikeKind::Ground || !(brightness > 0.0f) ||
      !(strike.positionMetres.y > strike.groundAltitudeMetres)) {
    return segments;
  }
  const std::uint64_t key = mix(strike.seed);
  const double height = strike.positionMetres.y - strike.groundAltitudeMetres;
  // Where it meets the ground: within a quarter of its height around the charge.
  const glm::dvec3 drift = jitter(key, 1000) * (0.25 * height);
  const glm::dvec3 ground(strike.positionMetres.x + drift.x, strike.groundAltitudeMetres,
                          strike.positionMetres.z + drift.z);
  const std::vector<glm::dvec3> channel =
      jaggedPath(strike.positionMetres, ground, kMainPieces, 0.2, key);
  const glm::vec3 radiance =
      glm::vec3(0.9f, 0.92f, 1.0f) * (strike.radiance * kChannelRadiance * brightness);
  appendPath(channel, radiance, kChannelWidthMetres, segments);
  // Branches off the channel's upper two thirds, down and outwards, a fifth to a third of its
  // height long.
  for (std::uint32_t b = 0; b < kBranches; ++b) {
    const std::uint64_t branchKey = mix(key ^ (b + 1));
    const auto start = static_cast<std::size_t>(2.0 + uniform(branchKey, 0) * (kMainPieces * 0.6));
    const glm::dvec3 along = glm::normalize(channel[start + 1] - channel[start]);
    glm::dvec3 sideways = jitter(branchKey, 1);
    sideways.y = 0.0;
    const glm::dvec3 direction =
        glm::normalize(along + 1.2 * sideways / std::max(glm::length(sideways), 1e-6));
    const double length = height * (0.2 + 0.13 * uniform(branchKey, 2));
    const std::vector<glm::dvec3> branch = jaggedPath(
        channel[start], channel[start] + direction * length, kBranchPieces, 0.25, branchKey);
    appendPath(branch, radiance * kBranchShare, kChannelWidthMetres * kBranchShare, segments);
  }
  return segments;
}

std::vector<LightningCell> stormCellsFromWeather(const clouds::Settings& settings,
                                                 std::uint32_t noiseSeed, glm::dvec2 centreMetres,
                                                 double withinMetres, std::uint32_t count,
                                                 float radiusMetres,
                                                 std::span<const clouds::WeatherRegion> regions) {
  struct Column {
    glm::dvec2 xz;
    double strength;
  };
  // A grid fine enough for the weather's features (a 512^2 map over its tile: ~60 m a texel at
  // the default 32 km tile; cumulonimbus columns are kilometres across).
  constexpr int kSteps = 96;
  std::vector<Column> columns;
  for (int j = 0; j <= kSteps; ++j) {
    for (int i = 0; i <= kSteps; ++i) {
      const glm::dvec2 xz = centreMetres + withinMetres * (glm::dvec2(i, j) * (2.0 / kSteps) - 1.0);
      const clouds::WeatherColumn w =
          clouds::proceduralWeatherAt(settings, noiseSeed, xz, 0.0, regions);
      if (w.type < 0.75f || w.coverage < 0.5f) continue;
      columns.push_back({xz, double(w.coverage) * w.density * (w.type - 0.5)});
    }
  }
  std::sort(columns.begin(), columns.end(),
            [](const Column& a, const Column& b) { return a.strength > b.strength; });
  const double altitude = settings.layerBottomMetres +
                          (double(settings.layerTopMetres) - settings.layerBottomMetres) / 3.0;
  std::vector<LightningCell> cells;
  for (const Column& c : columns) {
    if (cells.size() >= count) break;
    const bool apart = std::all_of(cells.begin(), cells.end(), [&](const LightningCell& cell) {
      return glm::length(glm::dvec2(cell.positionMetres.x, cell.positionMetres.z) - c.xz) >=
             radiusMetres;
    });
    if (apart) cells.push_back({glm::dvec3(c.xz.x, altitude, c.xz.y), radiusMetres});
  }
  return cells;
}

bool installLightning(engine::ecs::World& world, engine::ecs::Scheduler& scheduler) {
  bool storm = false;
  world.view<const LightningStorm>().each([&](const LightningStorm&) { storm = true; });
  if (!storm) return false;
  world.ctx().emplaceOrReplace<ActiveLightning>();
  scheduler.add(
      engine::ecs::Phase::Simulate, "lightning",
      [reader = engine::ecs::EventReader<TriggerLightning>{}](engine::ecs::World& w) mutable {
        const auto& time = w.ctx().get<engine::ecs::FrameTime>();
        const double now = time.elapsedSeconds;
        auto& lightning = w.ctx().get<ActiveLightning>();
        // This frame's strikes start in [the last frame's clock, now): a paused clock (a step
        // of 0) takes none, and a strike at a frame's end is the next frame's, once. A clock the
        // host set back starts over from its step.
        const std::optional<double> until = lightning.simulatedUntilSeconds;
        const double from = until && *until <= now ? *until : now - time.deltaSeconds;
        lightning.simulatedUntilSeconds = now;
        auto& active = lightning.strikes;
        auto& sent = w.events<LightningStrike>();
        std::vector<LightningStrike> started;
        // Changing weather sets the rate: storms start and stop striking with it.
        const CloudWeather* weather = nullptr;
        w.view<const CloudLayer, const CloudWeather>().each(
            [&](const CloudLayer&, const CloudWeather& cw) { weather = &cw; });
        w.view<const LightningStorm>().each([&](const LightningStorm& s) {
          const std::vector<LightningStrike> due = strikesBetween(s, from, now, weather);
          started.insert(started.end(), due.begin(), due.end());
          for (const TriggerLightning& t : reader.read(w.events<TriggerLightning>())) {
            if (s.cells.empty()) continue;
            LightningStrike strike;
            strike.positionMetres = s.cells.front().positionMetres;
            strike.radiusMetres = s.cells.front().radiusMetres;
            strike.energy = t.energy;
            strike.kind = t.kind;
            strike.startSeconds = now;
            strike.radiance = s.radiance;
            strike.seed = static_cast<std::uint32_t>(mix(mix(s.seed) ^ started.size()) ^
                                                     std::uint64_t(now * 1000.0));
            strike.groundAltitudeMetres = s.groundAltitudeMetres;
            started.push_back(strike);
          }
        });
        for (const LightningStrike& s : started) sent.send(s);
        active.insert(active.end(), started.begin(), started.end());
        std::erase_if(active, [&](const LightningStrike& s) {
          return now > s.startSeconds + s.durationSeconds;
        });
      });
  return true;
}

}  // namespace clouds::ecs
