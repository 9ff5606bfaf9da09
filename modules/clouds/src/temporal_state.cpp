#include "temporal_state.h"

#include "setting_effects.h"
#include "weather_regions.h"
#include "wind_displacement.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace clouds::detail {
namespace {

constexpr const char* kReuseOff = "temporal reuse off";

// Bayer order of a 2x2 tile: the offsets in increasing threshold.
constexpr std::uint32_t kBayer2[4][2] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};

float angleDegrees(const glm::vec3& a, const glm::vec3& b) {
  const float la = glm::length(a);
  const float lb = glm::length(b);
  if (la < 1e-6f || lb < 1e-6f) return 0.0f;
  return glm::degrees(std::acos(std::clamp(glm::dot(a / la, b / lb), -1.0f, 1.0f)));
}

glm::vec3 forwardOf(const glm::mat4& view) {
  // World -> view maps the forward direction to -Z: it is minus the third row of the rotation.
  return -glm::vec3(view[0][2], view[1][2], view[2][2]);
}

}  // namespace

glm::uvec2 tilePhase(std::uint32_t k, std::uint32_t n) {
  // The Bayer order of a k x k tile is recursive: the two lowest bits of n pick the 2 x 2
  // quadrant at the coarsest scale (offset k/2), the next two at half that scale, and so on
  // (k = 4: (0,0), (2,2), (2,0), (0,2), (1,1), (3,3), ...). Consecutive frames land far apart
  // and every k * k frames each offset is visited once.
  glm::uvec2 phase{0, 0};
  n %= std::max(k * k, 1u);
  for (std::uint32_t scale = k / 2; scale >= 1; scale /= 2, n /= 4) {
    phase += glm::uvec2(kBayer2[n % 4][0], kBayer2[n % 4][1]) * scale;
  }
  return phase;
}

bool cloudsLookDifferent(const Settings& a, const Settings& b) {
  return settingsDifferIn(kResetsHistory, a, b);
}

TemporalFrame TemporalState::plan(const FrameInputs& in, const Settings& s, VkExtent2D traceExtent,
                                  bool inHeroCloud, bool nearHeroCloud) {
  TemporalFrame frame;
  frame.insideHeroCloud = inHeroCloud;
  const double altitude = in.cameraPosition.y;
  frame.insideLayer = altitude > s.layerBottomMetres - s.insideLayerMarginMetres &&
                      altitude < s.layerTopMetres + s.insideLayerMarginMetres;
  const double nearField = s.nearFieldMetres;
  frame.nearField =
      nearField > 0.0 && (nearHeroCloud || (altitude > s.layerBottomMetres - nearField &&
                                            altitude < s.layerTopMetres + nearField));
  const glm::dvec2 windDisplacement = windDisplacementOf(in, s);
  // The share of the painted weather map that moved since the last frame (painted_weather.h).
  const float mapMoved = paintedWeatherChange(PaintedWeather::of(in), painted_);
  // And how far the weather regions moved (weather_regions.h).
  const float regionsMoved = weatherRegionsChange(in.weatherRegions, regions_);
  if (!havePrevious_) {
    frame.resetReason = forgotten_;
  } else if (in.reset) {
    frame.resetReason = "camera cut";
  } else if (traceExtent.width != traceExtent_.width || traceExtent.height != traceExtent_.height ||
             in.renderExtent.width != outputExtent_.width ||
             in.renderExtent.height != outputExtent_.height) {
    frame.resetReason = "resize";
  } else if (glm::length(in.cameraPosition - cameraPosition_) > s.historyResetDistanceMetres) {
    frame.resetReason = "camera jump";
  } else if (glm::length(windDisplacement - windDisplacement_) > s.historyResetDistanceMetres) {
    // The host's wind displacement jumped (a new clock, or a wind changed without its
    // integral): the noise moved against the weather map, and the history holds other clouds.
    frame.resetReason = "wind jump";
  } else if (angleDegrees(forwardOf(in.view), forwardOf(view_)) > s.historyResetAngleDegrees) {
    frame.resetReason = "camera turn";
  } else if (angleDegrees(in.sunDirection, sunDirection_) > s.relightResetDegrees ||
             glm::length(in.sunIlluminance - sunIlluminance_) >
                 s.relightResetRatio * std::max(glm::length(sunIlluminance_), 1e-3f)) {
    frame.resetReason = "relighting";
  } else if (cloudsLookDifferent(s, settings_)) {
    frame.resetReason = "settings changed";
  } else if (mapMoved > kPaintedWeatherTolerance) {
    // A different painted map (or back to the procedural one) at once; a blend into another
    // over seconds keeps the history. A host repainting the same image in place should set
    // FrameInputs::reset.
    frame.resetReason = "weather map changed";
  } else if (regionsMoved > kWeatherRegionTolerance) {
    // A region appeared, vanished, jumped or changed its look at once; one easing over seconds
    // keeps the history, as the settings do.
    frame.resetReason = "weather regions changed";
  } else if (frame.nearField != nearField_) {
    // The history held the whole ray and now must hold the far part only, or the reverse.
    frame.resetReason = frame.nearField ? "near field on" : "near field off";
  } else if (frame.nearField && s.nearFieldMetres != settings_.nearFieldMetres) {
    frame.resetReason = "near field moved";
  } else if (!s.temporalReuse) {
    frame.resetReason = kReuseOff;
  } else {
    frame.useHistory = true;
    frame.resetReason = "";
  }
  // With reuse off the history is not used but the sequence goes on (new jitter each frame, so
  // a host may average frames); any other reason starts it again, so the frame after a cut
  // equals a fresh renderer's.
  const bool keepSequence = frame.useHistory || frame.resetReason == kReuseOff;
  const bool restart = !keepSequence;
  frame.temporalIndex = restart ? 0 : temporalIndex_ + 1;
  const std::uint32_t k = tileSizeFor(s.updateInterval);
  // Without history every pixel must come from this frame: at most 2 x 2 tiles, filled in
  // spatially (4x the march of a 1-in-16 frame, for the frames that need it only). A camera
  // moving inside or near the layer or a hero cloud reprojects its history, but the cloud all
  // around it changes from frame to frame, and each ray's result depends much on where it
  // starts: it refreshes at Settings::movingInsideUpdateInterval (2 x 2 tiles by default). (At
  // High, 640x360, against the Reference: flying up into the base, 35.1 dB, where rebuilding
  // each frame without history, as production engines do here, gave 30.0; clouds_bench's
  // fly-through.)
  const bool movingInsideCloud =
      (frame.insideLayer || frame.insideHeroCloud) && in.cameraPosition != cameraPosition_;
  const std::uint32_t inside =
      tileSizeFor(std::min(s.updateInterval, s.movingInsideUpdateInterval));
  frame.tileSize = !frame.useHistory ? std::min(k, 2u) : movingInsideCloud ? inside : k;
  frame.phase = tilePhase(frame.tileSize, frame.temporalIndex);
  frame.upsampleTemporally = upsamplesTemporally(s);
  frame.useOutputHistory = frame.upsampleTemporally && frame.useHistory && wroteOutputHistory_;
  frame.cameraDelta = havePrevious_ ? in.cameraPosition - cameraPosition_ : glm::dvec3(0.0);
  frame.windDrift = havePrevious_ ? windDisplacement - windDisplacement_ : glm::dvec2(0.0);
  frame.secondsSinceHistory = havePrevious_ ? in.timeSeconds - timeSeconds_ : 0.0;
  // A superstorm turns its clouds whenever the clock runs: nothing stands still then.
  const bool noDrift = frame.windDrift == glm::dvec2(0.0) &&
                       !(frame.secondsSinceHistory != 0.0 && hasVortex(in.weatherRegions));
  frame.previousView = havePrevious_ ? view_ : in.view;
  frame.previousProjection = havePrevious_ ? projection_ : in.projection;
  frame.cloudsChanging = frame.useHistory && (settingsChangedIn(kResetsHistory, s, settings_) ||
                                              mapMoved > 0.0f || regionsMoved > 0.0f);
  // Led only with temporal upsampling: without it (Medium) the lead measured -1.1 to +0.1 dB
  // over a change from Sparse to Stormy (weather_transition_gpu_test.cpp, 2026-12-03), the
  // trace's history alone, clamped as the wind moves it, lagging less than the lead assumes.
  if (frame.cloudsChanging && leadTheLook_ && frame.upsampleTemporally) {
    const float area = static_cast<float>(frame.tileSize * frame.tileSize);
    const float w = std::clamp(s.temporalFreshWeight, 0.05f, 1.0f);
    frame.lookLeadFrames = (1.0f - w) / w * area + 0.5f * (area - 1.0f);
  }
  frame.still = havePrevious_ && frame.cameraDelta == glm::dvec3(0.0) && noDrift &&
                !frame.cloudsChanging && in.view == view_ && in.projection == projection_;
  // While nothing moves, a pixel's history stays where it is and changes only where a fresh
  // sample lands (1 in 16 of the trace's pixels, 1 in 64 of the output's at High): the passes
  // update it in place and store only those pixels. Otherwise they write the other image.
  frame.readHistory = latestHistory_;
  frame.writeHistory = frame.still && frame.useHistory ? latestHistory_ : 1u - latestHistory_;
  return frame;
}

Settings TemporalState::marchedSettings(const Settings& s, const TemporalFrame& frame) const {
  if (frame.lookLeadFrames == 0.0f) return s;
  Settings led = s;
  const auto lead = [&](float Settings::*field, float lo, float hi) {
    const float change = s.*field - settings_.*field;
    led.*field = std::clamp(s.*field + frame.lookLeadFrames * change, lo, hi);
  };
  lead(&Settings::coverage, 0.0f, 1.0f);
  lead(&Settings::cloudType, 0.0f, 1.0f);
  lead(&Settings::densityMultiplier, 0.0f, 1e6f);
  lead(&Settings::anvilBias, 0.0f, 1.0f);
  lead(&Settings::detailErosion, 0.0f, 1.0f);
  lead(&Settings::skewMetres, 0.0f, 20000.0f);
  lead(&Settings::windShearDegrees, -180.0f, 180.0f);
  return led;
}

std::span<const WeatherRegion> TemporalState::marchedRegions(const FrameInputs& in,
                                                             const TemporalFrame& frame) {
  if (frame.lookLeadFrames == 0.0f) return in.weatherRegions;
  marchedRegions_ = leadRegions(in.weatherRegions, regions_, frame.lookLeadFrames);
  return marchedRegions_;
}

void TemporalState::commit(const TemporalFrame& frame, const FrameInputs& in,
                           const Settings& settings, VkExtent2D traceExtent) {
  havePrevious_ = true;
  temporalIndex_ = frame.temporalIndex;
  latestHistory_ = frame.writeHistory;
  traceExtent_ = traceExtent;
  outputExtent_ = in.renderExtent;
  wroteOutputHistory_ = frame.upsampleTemporally;
  nearField_ = frame.nearField;
  cameraPosition_ = in.cameraPosition;
  view_ = in.view;
  projection_ = in.projection;
  sunDirection_ = in.sunDirection;
  sunIlluminance_ = in.sunIlluminance;
  windDisplacement_ = windDisplacementOf(in, settings);
  timeSeconds_ = in.timeSeconds;
  settings_ = settings;
  painted_ = PaintedWeather::of(in);
  regions_.assign(in.weatherRegions.begin(), in.weatherRegions.end());
}

}  // namespace clouds::detail
