#include "shadow_cascades.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "cloud_shadow_march.h"
#include "setting_effects.h"
#include "temporal_state.h"
#include "wind_displacement.h"

namespace clouds::detail {
namespace {

// A cascade is remade at once when its time is this old (s) or negative: the weather and the
// clouds' shapes have moved on from what the wind's drift can account for.
constexpr double kMaxCascadeAgeSeconds = 10.0;
// Fraction of a side over which a cascade blends into the next (fxcontracts/cloud_shadow.h).
constexpr float kBlendBand = 0.1f;

double angleDegrees(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)));
}

bool sameTerrain(const FrameInputs::Terrain& a, const FrameInputs::Terrain& b) {
  return a.heightView == b.heightView && a.originMetres == b.originMetres &&
         a.sizeMetres == b.sizeMetres && a.minAltitudeMetres == b.minAltitudeMetres &&
         a.maxAltitudeMetres == b.maxAltitudeMetres;
}

}  // namespace

ShadowBasis shadowBasis(const glm::vec3& sunDirection) {
  const float length = glm::length(sunDirection);
  const glm::vec3 sun =
      length > 1e-6f && std::isfinite(length) ? sunDirection / length : glm::vec3(0, 1, 0);
  ShadowBasis b;
  b.light = glm::normalize(glm::dvec3(shader::shadowLightDirection(sun)));
  const glm::dvec2 horizontal(b.light.z, -b.light.x);
  const double h = glm::length(horizontal);
  b.u = h > 1e-6 ? glm::dvec3(horizontal.x / h, 0.0, horizontal.y / h) : glm::dvec3(1, 0, 0);
  b.v = glm::normalize(glm::cross(b.light, b.u));
  return b;
}

double cascadeSideMetres(const Settings& s, std::uint32_t c) {
  return static_cast<double>(s.shadowNearSideMetres) *
         std::pow(static_cast<double>(s.shadowCascadeRatio), static_cast<double>(c));
}

std::uint32_t cascadeForTurn(std::uint64_t turn, std::uint32_t cascades) {
  if (cascades <= 1 || turn % 2 == 0) return 0;
  return 1 + static_cast<std::uint32_t>((turn / 2) % (cascades - 1));
}

CascadeJob ShadowCascades::placement(std::uint32_t c, const FrameInputs& in,
                                     const Settings& s) const {
  CascadeJob job;
  job.cascade = c;
  job.basis = shadowBasis(in.sunDirection);
  const double n = s.shadowMapResolution;
  job.texelMetres = cascadeSideMetres(s, c) / n;
  // The focus: the camera, or the cloud base below it when it flies higher (its shadows fall
  // on what it looks down at).
  const glm::dvec3 focus(in.cameraPosition.x,
                         std::clamp(in.cameraPosition.y, 0.0, double(s.layerBottomMetres)),
                         in.cameraPosition.z);
  const glm::dvec2 plane(glm::dot(focus, job.basis.u), glm::dot(focus, job.basis.v));
  const glm::dvec2 centreTexel = glm::floor(plane / job.texelMetres);
  const auto half = static_cast<std::int64_t>(s.shadowMapResolution / 2);
  job.cornerTexel = glm::i64vec2(static_cast<std::int64_t>(centreTexel.x) - half,
                                 static_cast<std::int64_t>(centreTexel.y) - half);
  return job;
}

bool ShadowCascades::stale(const Made& made, const CascadeJob& now, const FrameInputs& in,
                           const Settings& s) const {
  if (!made.valid || in.reset) return true;
  if (settingsDifferIn(kRemakesShadows, settings_, s) || cloudsLookDifferent(settings_, s)) {
    return true;
  }
  if (paintedWeatherChange(PaintedWeather::of(in), painted_) > kPaintedWeatherTolerance ||
      weatherRegionsChange(in.weatherRegions, regions_) > kWeatherRegionTolerance ||
      !sameTerrain(in.terrain, terrain_)) {
    return true;
  }
  if (angleDegrees(made.basis.light, now.basis.light) > double(s.relightResetDegrees)) return true;
  const double age = in.timeSeconds - made.timeSeconds;
  if (age < 0.0 || age > kMaxCascadeAgeSeconds) return true;
  // The focus left the middle half of the cascade (measured on this frame's grid).
  const auto quarter = static_cast<std::int64_t>(s.shadowMapResolution / 4);
  const glm::i64vec2 moved = now.cornerTexel - made.cornerTexel;
  const bool sameGrid = made.texelMetres == now.texelMetres;
  return !sameGrid || std::abs(moved.x) > quarter || std::abs(moved.y) > quarter;
}

ShadowPlan ShadowCascades::plan(const FrameInputs& in, const Settings& s) const {
  ShadowPlan plan;
  plan.nextTurn = turn_;
  std::vector<CascadeJob>& jobs = plan.jobs;
  const std::uint32_t cascades = std::min<std::uint32_t>(
      s.shadowCascades, static_cast<std::uint32_t>(fxcontracts::shader::kCloudShadowMaxCascades));
  if (cascades == 0) return plan;
  std::array<bool, fxcontracts::shader::kCloudShadowMaxCascades> chosen{};
  for (std::uint32_t c = 0; c < cascades; ++c) {
    CascadeJob job = placement(c, in, s);
    if (stale(made_[c], job, in, s)) {
      jobs.push_back(job);
      chosen[c] = true;
    }
  }
  // After a remake of all of them the turns begin again (with the finest).
  if (jobs.size() == cascades) plan.nextTurn = 0;
  const bool sameTerrainAndSteps = in.terrain.heightView != VK_NULL_HANDLE &&
                                   sameTerrain(in.terrain, terrain_) &&
                                   s.terrainShadowSteps == settings_.terrainShadowSteps;
  const auto keepTerrain = [&](const CascadeJob& job) {
    const Made& t = made_[job.cascade];
    return sameTerrainAndSteps && hasTerrain_[job.cascade] && t.valid &&
           t.cornerTexel == job.cornerTexel && t.texelMetres == job.texelMetres &&
           t.basis.light == job.basis.light && t.basis.u == job.basis.u;
  };
  if (s.shadowFramesPerCascade > 1) {
    // Remaking at once takes the frame (and may invalidate what the slices were made over).
    if (!jobs.empty()) {
      plan.abandonSlices = building_.has_value();
    } else {
      plan.slice = nextSlice(in, s, plan);
      if (plan.slice->first) plan.slice->job.keepTerrain = keepTerrain(plan.slice->job);
    }
  } else {
    plan.abandonSlices = building_.has_value();
    // Then the cascades whose turn it is, up to the per-frame budget (a frame that had to
    // remake some at once spends its budget on those).
    const std::uint32_t budget = std::min(s.shadowCascadesPerFrame, cascades);
    const std::uint64_t lastTurn = plan.nextTurn + 2 * cascades;
    for (; jobs.size() < budget && plan.nextTurn < lastTurn; ++plan.nextTurn) {
      const std::uint32_t c = cascadeForTurn(plan.nextTurn, cascades);
      if (chosen[c]) continue;
      jobs.push_back(placement(c, in, s));
      chosen[c] = true;
    }
  }
  for (CascadeJob& job : jobs) job.keepTerrain = keepTerrain(job);
  return plan;
}

CascadeSlice ShadowCascades::nextSlice(const FrameInputs& in, const Settings& s,
                                       ShadowPlan& plan) const {
  const std::uint32_t n = s.shadowMapResolution;
  const std::uint32_t rowsPerSlice = (n + s.shadowFramesPerCascade - 1) / s.shadowFramesPerCascade;
  // Go on with the cascade in the making while it would still be made now, as it was begun.
  if (building_) {
    const CascadeSlice& first = building_->first;
    const Made begun{true,
                     first.job.basis,
                     first.job.cornerTexel,
                     first.job.texelMetres,
                     building_->timeSeconds,
                     building_->windDisplacement};
    if (!stale(begun, placement(first.job.cascade, in, s), in, s) &&
        first.rowCount == rowsPerSlice) {
      CascadeSlice slice = first;
      slice.first = false;
      slice.firstRow = building_->rowsDone;
      slice.rowCount = std::min(rowsPerSlice, n - slice.firstRow);
      slice.last = slice.firstRow + slice.rowCount >= n;
      return slice;
    }
    plan.abandonSlices = true;
  }
  // Begin the cascade whose turn it is.
  const std::uint32_t cascades = std::min<std::uint32_t>(
      s.shadowCascades, static_cast<std::uint32_t>(fxcontracts::shader::kCloudShadowMaxCascades));
  CascadeSlice slice;
  slice.job = placement(cascadeForTurn(plan.nextTurn++, cascades), in, s);
  slice.cameraPosition = in.cameraPosition;
  slice.firstRow = 0;
  slice.rowCount = std::min(rowsPerSlice, n);
  slice.first = true;
  slice.last = slice.rowCount >= n;
  return slice;
}

void ShadowCascades::commit(const ShadowPlan& plan, const FrameInputs& in, const Settings& s) {
  const bool terrain = in.terrain.heightView != VK_NULL_HANDLE;
  const glm::dvec2 wind = windDisplacementOf(in, s);
  for (const CascadeJob& job : plan.jobs) {
    made_[job.cascade] =
        Made{true, job.basis, job.cornerTexel, job.texelMetres, in.timeSeconds, wind};
    hasTerrain_[job.cascade] = terrain;
  }
  if (plan.abandonSlices) building_.reset();
  if (plan.slice) {
    const CascadeSlice& slice = *plan.slice;
    if (slice.first) building_ = Building{slice, 0, in.timeSeconds, wind};
    building_->rowsDone = slice.firstRow + slice.rowCount;
    if (slice.last) {
      const CascadeJob& job = slice.job;
      made_[job.cascade] = Made{true,
                                job.basis,
                                job.cornerTexel,
                                job.texelMetres,
                                building_->timeSeconds,
                                building_->windDisplacement};
      hasTerrain_[job.cascade] = terrain;
      building_.reset();
    }
  }
  turn_ = plan.nextTurn;
  for (std::uint32_t c = s.shadowCascades; c < made_.size(); ++c) {
    made_[c] = Made{};
    hasTerrain_[c] = false;
  }
  settings_ = s;
  painted_ = PaintedWeather::of(in);
  regions_.assign(in.weatherRegions.begin(), in.weatherRegions.end());
  terrain_ = in.terrain;
}

ShadowMapParameters ShadowCascades::parameters(const glm::dvec3& camera,
                                               const glm::dvec2& windDisplacementMetres,
                                               const Settings& s) const {
  ShadowMapParameters p;
  std::uint32_t cascades = 0;
  for (std::uint32_t c = 0; c < s.shadowCascades && c < made_.size() && made_[c].valid; ++c) {
    const Made& m = made_[c];
    // Between refreshes the clouds drifted with the wind: a receiver now is shadowed by the
    // cloud that was upwind of it when the cascade was made.
    const glm::dvec2 wind = windDisplacementMetres - m.windDisplacement;
    const glm::dvec3 drift(wind.x, 0.0, wind.y);
    const double side = m.texelMetres * s.shadowMapResolution;
    const auto edge = [&](const glm::dvec3& axis, std::int64_t corner) {
      return static_cast<float>(static_cast<double>(corner) * m.texelMetres -
                                glm::dot(camera, axis) + glm::dot(drift, axis));
    };
    p.cascade[3 * c] = glm::vec4(glm::vec3(m.basis.u), edge(m.basis.u, m.cornerTexel.x));
    p.cascade[3 * c + 1] = glm::vec4(glm::vec3(m.basis.v), edge(m.basis.v, m.cornerTexel.y));
    p.cascade[3 * c + 2] = glm::vec4(glm::vec3(m.basis.light), static_cast<float>(1.0 / side));
    cascades = c + 1;
  }
  p.info = glm::vec4(static_cast<float>(cascades), static_cast<float>(s.shadowMapResolution),
                     static_cast<float>(camera.y), kBlendBand);
  return p;
}

shader::ShadowMapConstants shadowMapConstants(const CascadeJob& job, const glm::dvec3& camera,
                                              const Settings& s) {
  shader::ShadowMapConstants k{};
  const auto centre = [&](const glm::dvec3& axis, std::int64_t corner) {
    return static_cast<float>((static_cast<double>(corner) + 0.5) * job.texelMetres -
                              glm::dot(camera, axis));
  };
  k.axisU = glm::vec4(glm::vec3(job.basis.u), centre(job.basis.u, job.cornerTexel.x));
  k.axisV = glm::vec4(glm::vec3(job.basis.v), centre(job.basis.v, job.cornerTexel.y));
  k.light = glm::vec4(glm::vec3(job.basis.light), static_cast<float>(job.texelMetres));
  // The jitter's seed: the texel's place on the world grid (wrapping is harmless for a hash).
  k.worldTexel =
      glm::ivec2(static_cast<std::int32_t>(static_cast<std::uint32_t>(job.cornerTexel.x)),
                 static_cast<std::int32_t>(static_cast<std::uint32_t>(job.cornerTexel.y)));
  k.cascade = job.cascade;
  k.resolution = s.shadowMapResolution;
  k.steps = s.shadowSteps;
  k.flags = job.keepTerrain ? shader::kShadowTexelKeepTerrain : 0u;
  k.firstRow = 0;
  k.rowCount = s.shadowMapResolution;
  return k;
}

shader::TerrainShadowConstants terrainShadowConstants(const CascadeJob& job, const FrameInputs& in,
                                                      const Settings& s) {
  const FrameInputs::Terrain& terrain = in.terrain;
  shader::TerrainShadowConstants k{};
  k.cascade = shadowMapConstants(job, in.cameraPosition, s);
  k.heightOriginMetres =
      glm::vec2(terrain.originMetres - glm::dvec2(in.cameraPosition.x, in.cameraPosition.z));
  k.heightInverseSize = glm::vec2(1.0 / terrain.sizeMetres);
  k.minAltitudeMetres = terrain.minAltitudeMetres;
  k.maxAltitudeMetres = terrain.maxAltitudeMetres;
  // One texel (the rays of a texel's footprint differ by that much) and the fade below the
  // shadow's edge: a receiver at its own ray's exit from the ground stays lit.
  k.biasMetres =
      static_cast<float>(job.texelMetres) + fxcontracts::shader::kCloudShadowTerrainRampMetres;
  k.steps = s.terrainShadowSteps;
  k.cameraAltitudeMetres = static_cast<float>(in.cameraPosition.y);
  return k;
}

}  // namespace clouds::detail

// The public struct is the shaders' parameter block, field for field.
static_assert(sizeof(clouds::ShadowMapParameters) ==
              sizeof(fxcontracts::shader::CloudShadowParameters));
static_assert(offsetof(clouds::ShadowMapParameters, info) ==
              offsetof(fxcontracts::shader::CloudShadowParameters, info));
