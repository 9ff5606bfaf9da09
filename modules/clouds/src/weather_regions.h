#pragma once
// FrameInputs::weatherRegions on the CPU: their uniforms (cloud_weather_regions.h reads them),
// the bounds a frame's checks need (the fullest coverage, the densest multiplier), and how far
// they moved between two frames (the history and the shadow cascades keep what a region easing
// over seconds changes, and drop what one appearing or jumping changes).
#include <span>
#include <vector>

#include "cloud_types.h"
#include "clouds/clouds.h"

namespace clouds::detail {

// The most a region may move in one frame with the history kept: as the settings' 1% (of a
// look field's range, or of the region's blend distance for its place and size).
inline constexpr float kWeatherRegionTolerance = 0.01f;

// Whether one of the regions is a superstorm (WeatherRegion::vortex).
bool hasVortex(std::span<const WeatherRegion> regions);

// A superstorm's flow phases at `seconds` (CloudUniforms.vortexClock; cloud_vortex.h): each
// phase's clock restarts every period (a quarter of the wall's turn, in [10, 3600] s), the two
// half a period apart, each weighted by a triangle that is 0 at its restart. In double
// precision, so after any uptime the shaders see clocks under the period.
glm::vec4 vortexClock(const WeatherRegion& storm, double seconds);

// Over the surrounding weather and the regions: the largest coverage, and the largest density
// multiplier.
float fullestCoverage(const Settings& s, std::span<const WeatherRegion> regions);
float densestMultiplier(const Settings& s, std::span<const WeatherRegion> regions);

// The uniforms' density and regions: u.extinctionPerMetre at the densest multiplier, each
// column's scale of it, the fullest coverage, and the regions about the camera.
void setWeatherRegions(shader::CloudUniforms& u, const FrameInputs& in, const Settings& s);

// How far the regions moved from `a` to `b`: the largest change of a look field (of its range;
// the density multiplier's relative to the larger), of a region's place, size or turn (of its
// blend distance); 1 when their number differs. 0: the same regions.
float weatherRegionsChange(std::span<const WeatherRegion> a, std::span<const WeatherRegion> b);

// A weather texel as the march decodes it over the world column `xzMetres` under `settings`
// and `regions` (proceduralWeatherAt(), weatherAsMarched()) at `seconds` (a superstorm's bands
// turn).
WeatherColumn marchedColumn(glm::vec4 texel, const Settings& settings,
                            std::span<const WeatherRegion> regions, glm::dvec2 xzMetres,
                            double seconds);

// `now` with each region's look led by `frames` of its change since `before` (as
// TemporalState::marchedSettings leads the settings), within the fields' ranges; `now` as it is
// when the regions differ in number.
std::vector<WeatherRegion> leadRegions(std::span<const WeatherRegion> now,
                                       std::span<const WeatherRegion> before, float frames);

}  // namespace clouds::detail
