#include "uniforms.h"

#include "temporal_state.h"

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

// A frame without history inside the layer, made from a sparse pattern of its own rays (the
// tent of reconstruct.comp). When every trace pixel is marched (a tile of 1: the Reference,
// or reuse off at an update interval of 1) each pixel is its own ray, and a tent would only
// blur it.
bool rebuiltInsideLayer(const TemporalFrame& temporal) {
  return temporal.insideLayer && !temporal.useHistory && temporal.tileSize > 1;
}

}  // namespace

shader::CloudUniforms buildUniforms(const FrameInputs& in, const Settings& s,
                                    const UniformContext& context) {
  shader::CloudUniforms u{};
  u.inverseProjection = glm::inverse(in.projection);
  // The view's rotation only: the module is camera-relative. Transposing the upper 3x3 of a
  // rigid world->view transform gives view->world.
  u.viewToWorld = glm::mat4(glm::transpose(glm::mat3(in.view)));

  u.cameraAltitudeMetres = static_cast<float>(in.cameraPosition.y);
  u.planetRadiusMetres = s.planetRadiusMetres;
  u.layerBottomMetres = s.layerBottomMetres;
  u.layerTopMetres = s.layerTopMetres;

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

  const glm::dvec2 wind = glm::normalize(glm::dvec2(s.windDirection));
  const glm::dvec2 camera(in.cameraPosition.x, in.cameraPosition.z);
  // The noise moves with the wind; the weather map (coverage) stays where it is.
  const glm::dvec2 scrolled =
      camera + wind * (static_cast<double>(s.windSpeedMetresPerSecond) * in.timeSeconds);
  auto offset = [&](const glm::dvec2& p, double tile) {
    return glm::vec2(static_cast<float>(wrapToTile(p.x, tile)),
                     static_cast<float>(wrapToTile(p.y, tile)));
  };
  const glm::vec2 shape = offset(scrolled, s.shapeTileMetres);
  const glm::vec2 detail = offset(scrolled, s.detailTileMetres);
  u.shapeOffsetMetres = glm::vec3(shape.x, 0.0f, shape.y);
  u.shapeTileMetres = s.shapeTileMetres;
  u.detailOffsetMetres = glm::vec3(detail.x, 0.0f, detail.y);
  u.detailTileMetres = s.detailTileMetres;
  u.weatherOffsetMetres = offset(camera, s.weatherTileMetres);
  u.weatherTileMetres = s.weatherTileMetres;
  // One output pixel's angle (rad) at the centre of the view: the height of the near plane at
  // unit distance, 2 / |P[1][1]| for a perspective projection, over the output's rows.
  const float pixelsPerRadian =
      std::abs(in.projection[1][1]) * 0.5f * static_cast<float>(context.fullExtent.height);
  u.noiseFootprintPerMetre = s.noiseLevelOfDetail && pixelsPerRadian > 0.0f
                                 ? 1.0f / (pixelsPerRadian * s.noiseTexelsPerPixel)
                                 : 0.0f;
  u.curlOffsetMetres = offset(scrolled, s.curlTileMetres);
  u.curlTileMetres = s.curlTileMetres;
  u.curlStrengthMetres = s.curlStrengthMetres;
  u.windDirection = glm::vec2(wind);
  u.skewMetres = s.skewMetres;
  const float weatherTexel = s.weatherTileMetres / float(shader::kWeatherMapSize);
  u.fineCellMetres = weatherTexel * float(shader::kWeatherMapSize / shader::kWeatherMaxFineSize);
  u.coarseCellMetres =
      weatherTexel * float(shader::kWeatherMapSize / shader::kWeatherMaxCoarseSize);

  u.extinctionPerMetre = s.extinctionPerMetre * s.densityMultiplier;
  u.coverage = s.coverage;
  u.cloudType = s.cloudType;
  u.typeVariation = s.typeVariation;
  u.anvilBias = s.anvilBias;
  u.detailErosion = s.detailErosion;
  u.detailDistanceMetres = s.detailDistanceMetres;
  u.densityVariation = s.densityVariation;

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

  u.viewStepMetres = s.viewStepMetres;
  u.viewStepGrowth = s.viewStepGrowth;
  u.maxDistanceMetres = s.maxDistanceMetres;
  u.transmittanceCutoff = s.transmittanceCutoff;
  u.lightConeMetres = s.lightConeMetres;
  u.lightConeSpread = s.lightConeSpread;
  u.coarseStepFactor = s.coarseStepFactor;
  u.emptySamplesToCoarse = static_cast<float>(s.emptySamplesToCoarse);
  u.temporalIndex = context.temporal.temporalIndex;
  u.maxViewSteps = s.maxViewSteps;
  u.flags = (context.reversedZ ? shader::kFlagReversedZ : 0u) |
            (context.hasDepth ? shader::kFlagHasDepth : 0u) |
            (rebuiltInsideLayer(context.temporal) ? shader::kFlagRebuiltInsideLayer : 0u) |
            (marchesEdgeRays(s, context.temporal) ? shader::kFlagEdgeRays : 0u);

  u.traceExtent = glm::uvec2(context.traceExtent.width, context.traceExtent.height);
  u.outputExtent = glm::uvec2(context.fullExtent.width, context.fullExtent.height);

  // Reprojection: a point at `rel` from the camera now was at rel + (camera move) - (wind drift
  // of the clouds) from the history's camera, seen through its rotation and projection.
  // Folded here once per frame so that the passes take one matrix product per pixel: a view
  // direction goes straight to the history's clip space, and the camera offset is a constant.
  const glm::mat4 previousViewProjection =
      context.temporal.previousProjection * glm::mat4(glm::mat3(context.temporal.previousView));
  u.previousClipFromView = previousViewProjection * u.viewToWorld;
  const glm::dvec2 drift =
      wind * (static_cast<double>(s.windSpeedMetresPerSecond) * context.temporal.deltaSeconds);
  const glm::dvec3 moved = context.temporal.cameraDelta - glm::dvec3(drift.x, 0.0, drift.y);
  u.previousClipOrigin = previousViewProjection * glm::vec4(glm::vec3(moved), 1.0f);
  // While nothing moves, the history is exact: the first refresh of each pixel since the history
  // started replaces what the frame without history interpolated, the next ones average with
  // it (the mean of the pixel's rays), down to temporalStillFreshWeight.
  const std::uint32_t rounds = context.temporal.temporalIndex /
                               std::max(context.temporal.tileSize * context.temporal.tileSize, 1u);
  u.temporalFreshWeight = context.temporal.still ? std::max(1.0f / static_cast<float>(rounds + 1),
                                                            s.temporalStillFreshWeight)
                                                 : s.temporalFreshWeight;
  u.historyClampMargin = s.historyClampMargin;
  u.traceScale = s.traceScale;
  u.historyClampSpreadPixels = s.historyClampSpreadPixels;

  const std::uint32_t k = context.temporal.tileSize;
  const auto lastFresh = [&](std::uint32_t extent, std::uint32_t phase) {
    return extent > phase ? (extent - 1 - phase) / k * k + phase : phase;
  };
  u.tileSize = k;
  u.tilePhase = context.temporal.phase;
  u.lastFreshPixel = lastFresh(context.traceExtent.width, context.temporal.phase.x) |
                     lastFresh(context.traceExtent.height, context.temporal.phase.y) << 16u;
  // Rays move inside their pixels from one refresh of a pixel to the next. A pixel is
  // refreshed once per round of k x k frames, so the sequence advances once per round. Its
  // points are stratified over the output pixels a trace pixel covers (m x m of them at trace
  // scale 1/m): the first m x m rounds visit each output pixel once, in Bayer order, and later
  // rounds move inside them along a Halton (2, 3) sequence, so temporal upsampling gets an own
  // sample for every output pixel as early as possible. Temporal upsampling only moves the
  // rays while it accumulates: a frame rebuilt from its own samples wants them centred.
  const bool subpixel =
      s.jitter == Jitter::BayerHaltonSubpixel || context.temporal.useOutputHistory;
  const std::uint32_t m = s.traceScale <= 0.25f ? 4u : s.traceScale <= 0.5f ? 2u : 1u;
  // The frame after a reset (index 0) marches without accumulating: the rounds start at
  // index 1, so that its pixels' next refresh (index k * k) is still in round 0.
  const std::uint32_t index = context.temporal.useOutputHistory
                                  ? std::max(context.temporal.temporalIndex, 1u) - 1u
                                  : context.temporal.temporalIndex;
  const std::uint32_t round = index / (k * k);
  if (subpixel) {
    const glm::uvec2 outputPixel = tilePhase(m, round);
    const std::uint32_t n = (round / (m * m)) % 64u + 1u;
    const glm::vec2 inside(shader::halton(n, 2u), shader::halton(n, 3u));
    u.subpixelOffset = (glm::vec2(outputPixel) + inside) / float(m) - 0.5f;
  }
  // The rays' start offset moves along the rounds too; while the output pixels keep their own
  // samples, along each one's own visits (refreshStartOffset()).
  const std::uint32_t streams = context.temporal.useOutputHistory ? m * m : 1u;
  u.rayStartOffset = shader::refreshStartOffset(round, streams);
  // Edge rays go through the other output pixels of their trace pixel, at points that keep
  // the mean position of each output pixel's samples at its centre (else the accumulated image
  // is shifted: edge rays at this round's point moved by a third and two thirds of a pixel put
  // it 0.2 pixel off and scored 2.6 dB lower above the layer). The first goes through the pixel
  // beside this round's (the rays' visit half a cycle of output pixels later: at m 2 and 4 it
  // differs in x only) at the antithetic point, moved by half a pixel on both axes; the second
  // through the first's mirror image across the trace pixel's middle row, at its mirrored
  // point. They start a quarter and three quarters of a step from that visit's rays.
  if (marchesEdgeRays(s, context.temporal)) {
    u.edgeRaysPerTile = s.edgeRays;
    const std::uint32_t n = (round / (m * m)) % 64u + 1u;
    const glm::vec2 inside(shader::halton(n, 2u), shader::halton(n, 3u));
    const std::uint32_t visit = round + (m * m) / 2u;
    const glm::vec2 first =
        (glm::vec2(tilePhase(m, visit)) + glm::fract(inside + 0.5f)) / float(m) - 0.5f;
    u.edgeSubpixelOffsets = glm::vec4(first, first.x, -first.y);
    const float start = glm::fract(shader::refreshStartOffset(visit, streams) + 0.25f);
    u.edgeRayStartOffsets = glm::vec2(start, glm::fract(start + 0.5f));
  }
  u.lightRound = round;
  u.upsamplingMaxSamples = static_cast<float>(s.upsamplingMaxSamples);
  if (in.aerialPerspective.view != VK_NULL_HANDLE) {
    u.aerialPerspectiveScale = in.aerialPerspective.radianceScale;
    u.aerialPerspectiveRange = in.aerialPerspective.rangeMetres;
    u.aerialPerspectiveSlices = static_cast<float>(in.aerialPerspective.slices);
  }
  return u;
}

bool marchesEdgeRays(const Settings& s, const TemporalFrame& temporal) {
  return s.edgeRays > 0 && temporal.useOutputHistory && temporal.tileSize > 1;
}

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
                      s.edgeRays > 0 && upsamplesTemporally(s) ? 1u : 0u};
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

}  // namespace clouds::detail
