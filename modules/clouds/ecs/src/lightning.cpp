#include "clouds/ecs/lightning.h"

#include <algorithm>
#include <cmath>

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
                                            double toSeconds) {
  std::vector<LightningStrike> strikes;
  if (!(toSeconds > fromSeconds) || !std::isfinite(fromSeconds) || !std::isfinite(toSeconds)) {
    return strikes;
  }
  const double perSlot = std::clamp(storm.strikesPerMinute / 60.0 * kSlotSeconds, 0.0, 1.0);
  const auto first = static_cast<std::int64_t>(std::floor(fromSeconds / kSlotSeconds));
  const auto last = static_cast<std::int64_t>(std::floor(toSeconds / kSlotSeconds));
  for (std::size_t c = 0; c < storm.cells.size(); ++c) {
    for (std::int64_t slot = first; slot <= last; ++slot) {
      const std::uint64_t key =
          mix(mix(storm.seed) ^ mix(std::uint64_t(c) + 1)) ^ std::uint64_t(slot);
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
        const double before = now - time.deltaSeconds;
        auto& active = w.ctx().get<ActiveLightning>().strikes;
        auto& sent = w.events<LightningStrike>();
        std::vector<LightningStrike> started;
        w.view<const LightningStorm>().each([&](const LightningStorm& s) {
          // The first frame (no time passed yet) also takes strikes at time 0.
          const std::vector<LightningStrike> due =
              strikesBetween(s, time.deltaSeconds > 0.0 ? before : now, now + 1e-9);
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
