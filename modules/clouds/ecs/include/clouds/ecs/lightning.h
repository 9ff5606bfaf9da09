#pragma once
// Lightning as ECS data: storms are scene data (a LightningStorm entity: storm cells, a strike
// rate, a seed, the share of ground discharges), the "lightning" system turns them into
// LightningStrike events deterministically from the seed and the frame clock, and the
// strikes in progress glow inside the clouds (ActiveLightning, which the clouds' inputs read).
// A scene without a storm has no lightning system, no flashes' room in the clouds' settings
// and so no glow code in their pipelines.
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "clouds/clouds.h"
#include "clouds/ecs/cloud_components.h"
#include "clouds/weather.h"
#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"

namespace clouds::ecs {

// Where a storm's charge glows: a cell inside the cloud.
struct LightningCell {
  glm::dvec3 positionMetres{0.0};  // world
  float radiusMetres = 4000.0f;    // the glow's reach
};

struct LightningStorm {
  std::vector<LightningCell> cells;
  double strikesPerMinute = 6.0;  // each cell's mean rate (a Poisson process)
  std::uint32_t seed = 1;
  double groundFraction = 0.3;        // the share of strikes that discharge to the ground
  float radiance = 400.0f;            // the glow's radiance at a strike's peak (the host's units)
  double groundAltitudeMetres = 0.0;  // where ground discharges' bolts end (terrain hides the rest)
};

// Where a storm's cells are when the weather says: the `count` columns around `centreMetres`
// (x, z; within `withinMetres` along each axis) where the procedural weather holds the most
// cumulonimbus (coverage times density times how far the type is towards 1, among columns of
// type 0.75 or more and coverage 0.5 or more), each at least `radiusMetres` from the others,
// strongest first; each cell a third of the way up the layer, reaching `radiusMetres`. Fewer
// (or none) where the weather has fewer. A pure function (clouds::proceduralWeatherAt at time 0,
// under `regions`).
std::vector<LightningCell> stormCellsFromWeather(
    const clouds::Settings& settings, std::uint32_t noiseSeed, glm::dvec2 centreMetres,
    double withinMetres, std::uint32_t count, float radiusMetres,
    std::span<const clouds::WeatherRegion> regions = {});

enum class StrikeKind : std::uint32_t { IntraCloud, Ground };

// A strike: where and when it glows, how brightly, and its return strokes (real strokes come
// 3 or 4 to a flash, 40-60 ms apart, the flash lasting 0.2-0.5 s).
struct LightningStrike {
  glm::dvec3 positionMetres{0.0};
  float radiusMetres = 4000.0f;
  float energy = 1.0f;  // scales LightningStorm::radiance
  StrikeKind kind = StrikeKind::IntraCloud;
  double startSeconds = 0.0;
  double durationSeconds = 0.3;
  std::uint32_t strokes = 3;
  float radiance = 400.0f;            // the storm's, at the peak of a stroke
  std::uint32_t seed = 0;             // the shape of a ground discharge's bolt
  double groundAltitudeMetres = 0.0;  // the storm's: where the bolt ends
};

// A strike asked for now (a script's event, a key): at the storm's first cell.
struct TriggerLightning {
  float energy = 1.0f;
  StrikeKind kind = StrikeKind::IntraCloud;
};

// Context singleton: the strikes in progress this frame.
struct ActiveLightning {
  std::vector<LightningStrike> strikes;
  // The clock at the end of the last frame simulated: the next frame takes the strikes from
  // here on, so consecutive frames cover time without a gap or an overlap (now - dt need not
  // round back to it).
  std::optional<double> simulatedUntilSeconds;
};

// The strikes of `storm` that start in [fromSeconds, toSeconds), in order of start: a pure
// function of the storm (its seed) and the interval, so reruns and any frame rate give the
// same strikes. Each cell's clock is cut into 0.1 s slots; a hash of (seed, cell, slot)
// decides whether a strike starts in the slot (with the rate's probability) and when, how
// strong, which kind and how many strokes. With `weather` (changing weather) the rate of a
// cell in each slot is that of the weather over the cell at the slot's start instead of the
// storm's, so a storm starts and stops striking with the weather, and only where a region's
// weather strikes, as deterministically.
std::vector<LightningStrike> strikesBetween(const LightningStorm& storm, double fromSeconds,
                                            double toSeconds,
                                            const CloudWeather* weather = nullptr);

// A strike's brightness at `seconds` in [0, 1]: its return strokes, each a sharp rise and a
// 25 ms decay, 50 ms apart, the later ones weaker; 0 before it starts and after it ends.
float strikeEnvelope(const LightningStrike& strike, double seconds);

// A ground discharge's bolt, as straight pieces at `brightness` (its envelope times its
// energy): the channel from the strike's charge down to the storm's ground altitude, jagged
// by midpoint displacement, and a few dimmer branches off its upper part; a pure function of
// the strike (its seed). Nothing for an intra-cloud strike or no brightness.
// kBoltSegments pieces at most.
inline constexpr std::uint32_t kBoltSegments = 64;
std::vector<clouds::LightningBoltSegment> boltSegments(const LightningStrike& strike,
                                                       float brightness);

// Adds the "lightning" system (Simulate) when the world has a LightningStorm: it reads the
// frame clock and TriggerLightning events, sends a LightningStrike event for each strike that
// starts and keeps ActiveLightning. Returns whether it was added.
bool installLightning(engine::ecs::World& world, engine::ecs::Scheduler& scheduler);

}  // namespace clouds::ecs
