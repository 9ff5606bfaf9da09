#include "uniforms.h"

#include "temporal_state.h"
#include "weather_regions.h"
#include "wind_displacement.h"

#include <algorithm>
#include <cmath>

#include "cloud_math.h"
#include "phase_normaliser.h"

namespace clouds::detail {

double wrapToTile(double x, double tile) {
  const double r = std::fmod(x, tile);
  return r < 0.0 ? r + tile : r;
}

namespace {

// A frame without history inside the layer or a hero cloud's box, made from a sparse pattern of its
// own rays (the tent of reconstruct.comp). When every trace pixel is marched (a tile of 1: the
// Reference, or reuse off at an update interval of 1) each pixel is its own ray, and a tent would
// only blur it.
bool rebuiltInsideCloud(const TemporalFrame& temporal) {
  return (temporal.insideLayer || temporal.insideHeroCloud) && !temporal.useHistory &&
         temporal.tileSize > 1;
}

// World xz, unit: the noise scrolls along it, and so the history's clouds drift along it.
glm::dvec2 windDirectionOf(const Settings& s) {
  return glm::normalize(glm::dvec2(s.windDirection));
}

// A world position's offset (m) inside a tiling texture, reduced in double precision so that
// the GPU only sees small numbers.
glm::vec2 offsetInTile(const glm::dvec2& p, double tile) {
  return glm::vec2(static_cast<float>(wrapToTile(p.x, tile)),
                   static_cast<float>(wrapToTile(p.y, tile)));
}

void setCamera(shader::CloudUniforms& u, const FrameInputs& in) {
  u.inverseProjection = glm::inverse(in.projection);
  // The view's rotation only: the module is camera-relative. Transposing the upper 3x3 of a
  // rigid world->view transform gives view->world.
  u.viewToWorld = glm::mat4(glm::transpose(glm::mat3(in.view)));
}

void setPlanetAndLayer(shader::CloudUniforms& u, const FrameInputs& in, const Settings& s) {
  u.cameraAltitudeMetres = static_cast<float>(in.cameraPosition.y);
  u.planetRadiusMetres = s.planetRadiusMetres;
  u.layerBottomMetres = s.layerBottomMetres;
  u.layerTopMetres = s.layerTopMetres;
}

void setLight(shader::CloudUniforms& u, const FrameInputs& in, const Settings& s) {
  glm::vec3 sun = in.sunDirection;
  const float sunLength = glm::length(sun);
  sun = sunLength > 1e-6f && std::isfinite(sunLength) ? sun / sunLength : glm::vec3(0, 1, 0);
  u.sunDirection = sun;
  u.sunIlluminance = in.sunIlluminance;
  u.sunStrength = s.sunStrength;
  u.ambientTop = in.ambientTop;
  u.ambientStrength = s.ambientStrength;
  u.ambientBottom = in.ambientBottom;
  u.ambientOcclusionStrength = s.ambientOcclusionStrength;
}

// The camera's place in the shape, detail, curl and weather tiles, and the wind's lean.
void setNoisePlacement(shader::CloudUniforms& u, const FrameInputs& in, const Settings& s) {
  const glm::dvec2 wind = windDirectionOf(s);
  const glm::dvec2 camera(in.cameraPosition.x, in.cameraPosition.z);
  // The noise moves with the wind (a feature read at camera + offset + p lies at p: it is
  // carried downwind as the offset falls); the weather map (coverage) stays where it is.
  const glm::dvec2 scrolled = camera - windDisplacementOf(in, s);
  const glm::vec2 shape = offsetInTile(scrolled, s.shapeTileMetres);
  const glm::vec2 detail = offsetInTile(scrolled, s.detailTileMetres);
  u.shapeOffsetMetres = glm::vec3(shape.x, 0.0f, shape.y);
  u.shapeTileMetres = s.shapeTileMetres;
  u.detailOffsetMetres = glm::vec3(detail.x, 0.0f, detail.y);
  u.detailTileMetres = s.detailTileMetres;
  u.weatherOffsetMetres = offsetInTile(camera, s.weatherTileMetres);
  u.weatherTileMetres = s.weatherTileMetres;
  u.curlOffsetMetres = offsetInTile(scrolled, s.curlTileMetres);
  u.curlTileMetres = s.curlTileMetres;
  u.curlStrengthMetres = s.curlStrengthMetres;
  u.windDirection = glm::vec2(wind);
  u.skewMetres = s.skewMetres;
  u.windShearRadians = glm::radians(s.windShearDegrees);
}

// The noise's level of detail: the texel width (m) whose mip level a sample reads, per metre
// of distance; 0 reads the finest level everywhere.
float noiseFootprintPerMetre(const FrameInputs& in, const Settings& s, VkExtent2D fullExtent) {
  // One output pixel's angle (rad) at the centre of the view: the height of the near plane at
  // unit distance, 2 / |P[1][1]| for a perspective projection, over the output's rows.
  const float pixelsPerRadian =
      std::abs(in.projection[1][1]) * 0.5f * static_cast<float>(fullExtent.height);
  return s.noiseLevelOfDetail && pixelsPerRadian > 0.0f
             ? 1.0f / (pixelsPerRadian * s.noiseTexelsPerPixel)
             : 0.0f;
}

// Empty-space skipping jumps over the cells of the weather map's fine and coarse maxima.
void setWeatherCells(shader::CloudUniforms& u, const Settings& s) {
  const float weatherTexel = s.weatherTileMetres / float(shader::kWeatherMapSize);
  u.fineCellMetres = weatherTexel * float(shader::kWeatherMapSize / shader::kWeatherMaxFineSize);
  u.coarseCellMetres =
      weatherTexel * float(shader::kWeatherMapSize / shader::kWeatherMaxCoarseSize);
}

void setDensity(shader::CloudUniforms& u, const FrameInputs& in, const Settings& s) {
  setWeatherRegions(u, in, s);  // the extinction, and the regions' look about it
  u.coverage = s.coverage;
  u.cloudType = s.cloudType;
  u.typeVariation = s.typeVariation;
  u.anvilBias = s.anvilBias;
  u.detailErosion = s.detailErosion;
  u.detailDistanceMetres = s.detailDistanceMetres;
  u.densityVariation = s.densityVariation;
}

// The phase lobes, multiple scattering and the silver lining, with the normalisers that give
// back the energy the silver lining's max() gains.
void setScattering(shader::CloudUniforms& u, const Settings& s) {
  u.phaseForwardG = s.phaseForwardG;
  u.phaseBackwardG = s.phaseBackwardG;
  u.phaseBackwardWeight = s.phaseBackwardWeight;
  u.albedo = s.albedo;
  u.msOctaves = static_cast<float>(s.multipleScatteringOctaves);
  u.msExtinctionScale = s.msExtinctionScale;
  u.msContribution = s.msContribution;
  u.msEccentricityScale = s.msEccentricityScale;
  u.inScatterStrength = s.inScatterStrength;
  u.inScatterCoreProfile = s.inScatterCoreProfile;
  u.silverIntensity = s.silverIntensity;
  u.silverG = shader::kMaxPhaseG - s.silverSpread;
  OctavePhaseSettings phaseSettings;
  phaseSettings.lobes = PhaseLobes{s.phaseForwardG, s.phaseBackwardG, s.phaseBackwardWeight,
                                   u.silverG, s.silverIntensity};
  phaseSettings.eccentricityScale = s.msEccentricityScale;
  const std::array<float, 8> inverses = octavePhaseNormaliserInverses(phaseSettings);
  u.phaseNormaliserInverseLow = glm::vec4(inverses[0], inverses[1], inverses[2], inverses[3]);
  u.phaseNormaliserInverseHigh = glm::vec4(inverses[4], inverses[5], inverses[6], inverses[7]);
}

// The view ray's steps, the light cone, and the frame's flags.
void setMarch(shader::CloudUniforms& u, const Settings& s, const UniformContext& context) {
  u.viewStepMetres = s.viewStepMetres;
  u.viewStepGrowth = s.viewStepGrowth;
  u.maxDistanceMetres = s.maxDistanceMetres;
  u.transmittanceCutoff = s.transmittanceCutoff;
  u.lightConeMetres = s.lightConeMetres;
  u.lightConeSpread = s.lightConeSpread;
  u.coarseStepFactor = s.coarseStepFactor;
  u.emptySamplesToCoarse = static_cast<float>(s.emptySamplesToCoarse);
  u.maxViewSteps = s.maxViewSteps;
  u.flags = (context.reversedZ ? shader::kFlagReversedZ : 0u) |
            (context.hasDepth ? shader::kFlagHasDepth : 0u) |
            (rebuiltInsideCloud(context.temporal) ? shader::kFlagRebuiltInsideCloud : 0u) |
            (marchesEdgeRays(s, context.temporal) ? shader::kFlagEdgeRays : 0u);
}

// The extents, and which pixel of each k x k tile this frame marches.
void setTiles(shader::CloudUniforms& u, const UniformContext& context) {
  u.traceExtent = glm::uvec2(context.traceExtent.width, context.traceExtent.height);
  u.outputExtent = glm::uvec2(context.fullExtent.width, context.fullExtent.height);
  u.temporalIndex = context.temporal.temporalIndex;
  const std::uint32_t k = context.temporal.tileSize;
  const auto lastFresh = [&](std::uint32_t extent, std::uint32_t phase) {
    return extent > phase ? (extent - 1 - phase) / k * k + phase : phase;
  };
  u.tileSize = k;
  u.tilePhase = context.temporal.phase;
  u.lastFreshPixel = lastFresh(context.traceExtent.width, context.temporal.phase.x) |
                     lastFresh(context.traceExtent.height, context.temporal.phase.y) << 16u;
}

// Reprojection: a point at `rel` from the camera now was at rel + (camera move) - (wind drift
// of the clouds) from the history's camera, seen through its rotation and projection.
// Folded here once per frame so that the passes take one matrix product per pixel: a view
// direction goes straight to the history's clip space, and the camera offset is a constant.
// Reads u.viewToWorld (setCamera()).
// A superstorm's turn since the history's frame moves each point further (cloud_temporal.h):
// its interval, and the history's view-projection for the move.
void setReprojection(shader::CloudUniforms& u, const Settings& s, const TemporalFrame& temporal) {
  const glm::mat4 previousViewProjection =
      temporal.previousProjection * glm::mat4(glm::mat3(temporal.previousView));
  u.previousClipFromView = previousViewProjection * u.viewToWorld;
  u.previousClipFromWorld = previousViewProjection;
  u.vortexHistorySeconds =
      s.vortexReprojection ? static_cast<float>(temporal.secondsSinceHistory) : 0.0f;
  const glm::dvec2 drift = temporal.windDrift;
  const glm::dvec3 moved = temporal.cameraDelta - glm::dvec3(drift.x, 0.0, drift.y);
  u.previousClipOrigin = previousViewProjection * glm::vec4(glm::vec3(moved), 1.0f);
  u.cameraMovedMetres = static_cast<float>(glm::length(moved));
}

// How fresh samples blend with the history, and how far the history is clamped.
void setHistoryBlend(shader::CloudUniforms& u, const Settings& s, const TemporalFrame& temporal) {
  // While nothing moves, the history is exact: the first refresh of each pixel since the history
  // started replaces what the frame without history interpolated, the next ones average with
  // it (the mean of the pixel's rays), down to temporalStillFreshWeight.
  const std::uint32_t rounds =
      temporal.temporalIndex / std::max(temporal.tileSize * temporal.tileSize, 1u);
  u.temporalFreshWeight =
      temporal.still ? std::max(1.0f / static_cast<float>(rounds + 1), s.temporalStillFreshWeight)
                     : s.temporalFreshWeight;
  u.historyClampMargin = s.historyClampMargin;
  u.traceScale = s.traceScale;
  u.historyClampSpreadPixels = s.historyClampSpreadPixels;
  u.upsamplingMaxSamples = static_cast<float>(s.upsamplingMaxSamples);
}

// Where this frame's rays sit in the sequence of a pixel's refreshes.
struct RefreshRound {
  std::uint32_t round = 0;    // a pixel is refreshed once per round of k x k frames
  std::uint32_t m = 1;        // output pixels per trace pixel, per axis (trace scale 1/m)
  std::uint32_t streams = 1;  // start-offset sequences: one per output pixel while they keep
                              //   their own samples
};

RefreshRound refreshRound(const Settings& s, const TemporalFrame& temporal) {
  RefreshRound r;
  const std::uint32_t k = temporal.tileSize;
  r.m = s.traceScale <= 0.25f ? 4u : s.traceScale <= 0.5f ? 2u : 1u;
  // The frame after a reset (index 0) marches without accumulating: the rounds start at
  // index 1, so that its pixels' next refresh (index k * k) is still in round 0.
  const std::uint32_t index = temporal.useOutputHistory ? std::max(temporal.temporalIndex, 1u) - 1u
                                                        : temporal.temporalIndex;
  r.round = index / (k * k);
  r.streams = temporal.useOutputHistory ? r.m * r.m : 1u;
  return r;
}

// Where this round's rays sit inside their output pixel: a Halton (2, 3) point that moves on
// once per cycle of m x m rounds (one visit to each output pixel).
glm::vec2 haltonInsidePixel(const RefreshRound& r) {
  const std::uint32_t n = (r.round / (r.m * r.m)) % 64u + 1u;
  return glm::vec2(shader::halton(n, 2u), shader::halton(n, 3u));
}

// Rays move inside their pixels from one refresh of a pixel to the next. A pixel is
// refreshed once per round of k x k frames, so the sequence advances once per round. Its
// points are stratified over the output pixels a trace pixel covers (m x m of them at trace
// scale 1/m): the first m x m rounds visit each output pixel once, in Bayer order, and later
// rounds move inside them along a Halton (2, 3) sequence, so temporal upsampling gets an own
// sample for every output pixel as early as possible. Temporal upsampling only moves the
// rays while it accumulates: a frame rebuilt from its own samples wants them centred.
void setRayPlacement(shader::CloudUniforms& u, const Settings& s, const TemporalFrame& temporal,
                     const RefreshRound& r) {
  const bool subpixel = s.jitter == Jitter::BayerHaltonSubpixel || temporal.useOutputHistory;
  if (subpixel) {
    const glm::uvec2 outputPixel = tilePhase(r.m, r.round);
    u.subpixelOffset = (glm::vec2(outputPixel) + haltonInsidePixel(r)) / float(r.m) - 0.5f;
  }
  // The rays' start offset moves along the rounds too; while the output pixels keep their own
  // samples, along each one's own visits (refreshStartOffset()).
  u.rayStartOffset = shader::refreshStartOffset(r.round, r.streams);
  u.lightRound = r.round;
}

// Edge rays go through the other output pixels of their trace pixel, at points that keep
// the mean position of each output pixel's samples at its centre (else the accumulated image
// is shifted: edge rays at this round's point moved by a third and two thirds of a pixel put
// it 0.2 pixel off and scored 2.6 dB lower above the layer). The first goes through the pixel
// beside this round's (the rays' visit half a cycle of output pixels later: at m 2 and 4 it
// differs in x only) at the antithetic point, moved by half a pixel on both axes; the second
// through the first's mirror image across the trace pixel's middle row, at its mirrored
// point. They start a quarter and three quarters of a step from that visit's rays.
void setEdgeRays(shader::CloudUniforms& u, const Settings& s, const RefreshRound& r) {
  u.edgeRaysPerTile = s.edgeRays;
  const std::uint32_t visit = r.round + (r.m * r.m) / 2u;
  const glm::vec2 first =
      (glm::vec2(tilePhase(r.m, visit)) + glm::fract(haltonInsidePixel(r) + 0.5f)) / float(r.m) -
      0.5f;
  u.edgeSubpixelOffsets = glm::vec4(first, first.x, -first.y);
  const float start = glm::fract(shader::refreshStartOffset(visit, r.streams) + 0.25f);
  u.edgeRayStartOffsets = glm::vec2(start, glm::fract(start + 0.5f));
}

void setAerialPerspective(shader::CloudUniforms& u, const FrameInputs& in) {
  if (in.aerialPerspective.view == VK_NULL_HANDLE) return;
  u.aerialPerspectiveScale = in.aerialPerspective.radianceScale;
  u.aerialPerspectiveRange = in.aerialPerspective.rangeMetres;
  u.aerialPerspectiveSlices = static_cast<float>(in.aerialPerspective.slices);
}

}  // namespace

shader::CloudUniforms buildUniforms(const FrameInputs& in, const Settings& s,
                                    const UniformContext& context) {
  shader::CloudUniforms u{};
  setCamera(u, in);
  setPlanetAndLayer(u, in, s);
  setLight(u, in, s);
  setNoisePlacement(u, in, s);
  u.noiseFootprintPerMetre = noiseFootprintPerMetre(in, s, context.fullExtent);
  setWeatherCells(u, s);
  setDensity(u, in, s);
  setScattering(u, s);
  setMarch(u, s, context);
  setTiles(u, context);
  u.nearFieldMetres = context.temporal.nearField ? s.nearFieldMetres : 0.0f;
  const VkExtent2D nearField = nearFieldExtentFor(context.traceExtent);
  u.nearFieldExtent = glm::uvec2(nearField.width, nearField.height);
  setReprojection(u, s, context.temporal);
  setHistoryBlend(u, s, context.temporal);
  const RefreshRound round = refreshRound(s, context.temporal);
  setRayPlacement(u, s, context.temporal, round);
  if (marchesEdgeRays(s, context.temporal)) setEdgeRays(u, s, round);
  setAerialPerspective(u, in);
  return u;
}

bool marchesEdgeRays(const Settings& s, const TemporalFrame& temporal) {
  return s.edgeRays > 0 && temporal.useOutputHistory && temporal.tileSize > 1;
}

static_assert(static_cast<std::uint32_t>(HeroLight::Cone) == shader::kHeroLightCone &&
              static_cast<std::uint32_t>(HeroLight::Volume) == shader::kHeroLightVolume &&
              static_cast<std::uint32_t>(HeroLight::Marched) == shader::kHeroLightMarched);

MarchVariant marchVariant(const Settings& s) {
  // Temporal upsampling moves the rays inside their pixels (u.subpixel; zero while it does
  // not accumulate), which is jitter mode 2.
  const Jitter jitter = upsamplesTemporally(s) ? Jitter::BayerHaltonSubpixel : s.jitter;
  return MarchVariant{static_cast<std::uint32_t>(jitter),
                      s.detail ? 1u : 0u,
                      s.cheapSampling ? 1u : 0u,
                      s.multipleScattering ? 1u : 0u,
                      s.lightSteps,
                      s.emptySpaceSkipping ? 1u : 0u,
                      s.lightEveryOtherStep ? 1u : 0u,
                      s.edgeRays > 0 && upsamplesTemporally(s) ? 1u : 0u,
                      static_cast<std::uint32_t>(s.heroLight)};
}

VkDeviceSize edgeRayListBytes(VkExtent2D traceExtent) {
  const VkDeviceSize tiles =
      VkDeviceSize{(traceExtent.width + 1) / 2} * VkDeviceSize{(traceExtent.height + 1) / 2};
  return shader::kEdgeRayListHeaderBytes + tiles * sizeof(std::uint32_t);
}

VkExtent2D traceExtentFor(VkExtent2D full, float traceScale) {
  const auto scaled = [&](std::uint32_t v) {
    return std::max(1u, static_cast<std::uint32_t>(std::ceil(double(v) * double(traceScale))));
  };
  return {scaled(full.width), scaled(full.height)};
}

VkExtent2D nearFieldExtentFor(VkExtent2D trace) {
  return {(trace.width + 1) / 2, (trace.height + 1) / 2};
}

}  // namespace clouds::detail
