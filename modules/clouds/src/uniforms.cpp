#include "uniforms.h"

#include "temporal_state.h"

#include <algorithm>
#include <cmath>

#include "cloud_math.h"

namespace clouds::detail {

double wrapToTile(double x, double tile) {
  const double r = std::fmod(x, tile);
  return r < 0.0 ? r + tile : r;
}

shader::CloudUniforms buildUniforms(const FrameInputs& in, const Settings& s,
                                    const UniformContext& context) {
  shader::CloudUniforms u{};
  u.inverseProjection = glm::inverse(in.projection);
  // The view's rotation only: the module is camera-relative. Transposing the upper 3x3 of a
  // rigid world->view transform gives view->world.
  u.viewToWorld = glm::mat4(glm::transpose(glm::mat3(in.view)));

  u.planet = glm::vec4(static_cast<float>(in.cameraPosition.y), s.planetRadiusMetres,
                       s.layerBottomMetres, s.layerTopMetres);
  glm::vec3 sun = in.sunDirection;
  const float sunLength = glm::length(sun);
  sun = sunLength > 1e-6f && std::isfinite(sunLength) ? sun / sunLength : glm::vec3(0, 1, 0);
  u.sunDirection = glm::vec4(sun, 0.0f);
  u.sunIlluminance = glm::vec4(in.sunIlluminance, 0.0f);
  u.ambientTop = glm::vec4(in.ambientTop, 0.0f);
  u.ambientBottom = glm::vec4(in.ambientBottom, 0.0f);

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
  const glm::vec2 curl = offset(scrolled, s.curlTileMetres);
  const glm::vec2 weather = offset(camera, s.weatherTileMetres);
  u.shapeNoise = glm::vec4(shape.x, 0.0f, shape.y, s.shapeTileMetres);
  u.detailNoise = glm::vec4(detail.x, 0.0f, detail.y, s.detailTileMetres);
  u.weather = glm::vec4(weather.x, weather.y, s.weatherTileMetres, 0.0f);
  u.curl = glm::vec4(curl.x, curl.y, s.curlTileMetres, s.curlStrengthMetres);
  u.wind = glm::vec4(static_cast<float>(wind.x), static_cast<float>(wind.y), s.skewMetres, 0.0f);

  u.density = glm::vec4(s.extinctionPerMetre * s.densityMultiplier, s.coverage, s.cloudType,
                        s.typeVariation);
  u.shape = glm::vec4(s.anvilBias, s.detailErosion, s.detailDistanceMetres, s.densityVariation);
  u.phase = glm::vec4(s.phaseForwardG, s.phaseBackwardG, s.phaseBackwardWeight, s.albedo);
  u.multipleScattering = glm::vec4(static_cast<float>(s.multipleScatteringOctaves),
                                   s.msExtinctionScale, s.msContribution, s.msEccentricityScale);
  u.artistic =
      glm::vec4(s.inScatterStrength, s.ambientOcclusionStrength, s.ambientStrength, s.sunStrength);
  u.inScatter = glm::vec4(s.inScatterDepthMetres, 0.0f, 0.0f, 0.0f);
  u.march =
      glm::vec4(s.viewStepMetres, s.viewStepGrowth, s.maxDistanceMetres, s.transmittanceCutoff);
  u.light = glm::vec4(s.lightConeMetres, s.lightConeSpread, s.coarseStepFactor,
                      static_cast<float>(s.emptySamplesToCoarse));
  std::uint32_t flags = 0;
  if (context.reversedZ) flags |= shader::kFlagReversedZ;
  if (context.hasDepth) flags |= shader::kFlagHasDepth;
  u.frame = glm::uvec4(context.temporalIndex, s.maxViewSteps, flags, 0u);
  u.extent = glm::uvec4(context.traceExtent.width, context.traceExtent.height,
                        context.fullExtent.width, context.fullExtent.height);

  // Reprojection: a point at `rel` from the camera now was at rel + (camera move) - (wind drift
  // of the clouds) from last frame's camera, seen through last frame's rotation and projection.
  // Folded here once per frame so that the passes take one matrix product per pixel: a view
  // direction goes straight to last frame's clip space, and the camera offset is a constant.
  const glm::mat4 previousViewProjection =
      in.previousProjection * glm::mat4(glm::mat3(in.previousView));
  u.previousClipFromView = previousViewProjection * u.viewToWorld;
  const glm::dvec2 drift =
      wind * (static_cast<double>(s.windSpeedMetresPerSecond) * context.deltaSeconds);
  const glm::dvec3 moved = context.cameraDelta - glm::dvec3(drift.x, 0.0, drift.y);
  u.reprojection = glm::vec4(glm::vec3(moved), context.useHistory ? 1.0f : 0.0f);
  u.previousClipOrigin = previousViewProjection * glm::vec4(glm::vec3(moved), 1.0f);
  u.temporal = glm::vec4(s.temporalFreshWeight, s.historyClampMargin, s.traceScale,
                         s.historyClampSpreadPixels);
  const std::uint32_t k = context.tileSize;
  const auto lastFresh = [&](std::uint32_t extent, std::uint32_t phase) {
    return extent > phase ? (extent - 1 - phase) / k * k + phase : phase;
  };
  u.pattern = glm::uvec4(k, context.phase.x, context.phase.y,
                         lastFresh(context.traceExtent.width, context.phase.x) |
                             lastFresh(context.traceExtent.height, context.phase.y) << 16u);
  // Rays move inside their pixels from one refresh of a pixel to the next. A pixel is
  // refreshed once per round of k x k frames, so the sequence advances once per round. Its
  // points are stratified over the output pixels a trace pixel covers (m x m of them at trace
  // scale 1/m): the first m x m rounds visit each output pixel once, in Bayer order, and later
  // rounds move inside them along a Halton (2, 3) sequence, so temporal upsampling gets an own
  // sample for every output pixel as early as possible. Temporal upsampling only moves the
  // rays while it accumulates: a frame rebuilt from its own samples wants them centred.
  const bool subpixel = s.jitter == Jitter::BayerHaltonSubpixel || context.useOutputHistory;
  if (subpixel) {
    const std::uint32_t m = s.traceScale <= 0.25f ? 4u : s.traceScale <= 0.5f ? 2u : 1u;
    // The frame after a reset (index 0) marches without accumulating: the rounds start at
    // index 1, so that its pixels' next refresh (index k * k) is still in round 0.
    const std::uint32_t index =
        context.useOutputHistory ? std::max(context.temporalIndex, 1u) - 1u : context.temporalIndex;
    const std::uint32_t round = index / (k * k);
    const glm::uvec2 outputPixel = tilePhase(m, round);
    const std::uint32_t n = (round / (m * m)) % 64u + 1u;
    const glm::vec2 inside(shader::halton(n, 2u), shader::halton(n, 3u));
    u.subpixel = glm::vec4((glm::vec2(outputPixel) + inside) / float(m) - 0.5f, 0.0f, 0.0f);
  }
  u.upsampling = glm::vec4(static_cast<float>(s.upsamplingMaxSamples), 0.0f, 0.0f, 0.0f);
  const float weatherTexel = s.weatherTileMetres / float(shader::kWeatherMapSize);
  u.emptySpace = glm::vec4(
      weatherTexel * float(shader::kWeatherMapSize / shader::kWeatherMaxFineSize),
      weatherTexel * float(shader::kWeatherMapSize / shader::kWeatherMaxCoarseSize), 0.0f, 0.0f);
  return u;
}

MarchVariant marchVariant(const Settings& s) {
  // Temporal upsampling moves the rays inside their pixels (u.subpixel; zero while it does
  // not accumulate), which is jitter mode 2.
  const Jitter jitter = upsamplesTemporally(s) ? Jitter::BayerHaltonSubpixel : s.jitter;
  return MarchVariant{
      static_cast<std::uint32_t>(jitter), s.detail ? 1u : 0u, s.cheapSampling ? 1u : 0u,
      s.multipleScattering ? 1u : 0u,     s.lightSteps,       s.emptySpaceSkipping ? 1u : 0u};
}

VkExtent2D traceExtentFor(VkExtent2D full, float traceScale) {
  const auto scaled = [&](std::uint32_t v) {
    return std::max(1u, static_cast<std::uint32_t>(std::ceil(double(v) * double(traceScale))));
  };
  return {scaled(full.width), scaled(full.height)};
}

}  // namespace clouds::detail
