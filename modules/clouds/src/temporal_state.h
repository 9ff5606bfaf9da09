#pragma once
// The temporal reconstruction's bookkeeping, as plain logic (unit-tested without a GPU): per
// frame it decides whether last frame's result can be reprojected (or why not: reset, resize,
// a jump or turn of the camera, relighting, new settings, weather map or regions, a jump of the
// wind's displacement), which pixel of each tile the march refreshes (more of them while the camera
// moves in or near the cloud layer), and which history image is read and written. It is the one
// owner of "previous": the camera, sun and time the history was made with, recorded by commit() and
// used by the next plan().
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "clouds/clouds.h"
#include "painted_weather.h"

namespace clouds::detail {

struct TemporalFrame {
  bool useHistory = false;
  const char* resetReason = "first frame";
  bool insideLayer = false;
  bool insideHeroCloud = false;  // in or near a hero cloud's box (cameraInHeroCloudBox())
  // The near field is marched apart (Settings::nearFieldMetres > 0, the camera within that of
  // the layer or of a hero cloud's box); the history holds only the far part then.
  bool nearField = false;
  std::uint32_t tileSize = 1;       // k: one pixel per k x k tile is marched
  glm::uvec2 phase{0, 0};           // that pixel's offset in its tile
  std::uint32_t temporalIndex = 0;  // frames since the history was last reset
  std::uint32_t readHistory = 0;    // history image holding last frame's result
  std::uint32_t writeHistory = 1;   // history image this frame writes (the same when still)
  // Temporal upsampling (Settings::temporalUpsampling): this frame accumulates into the
  // output-resolution history, and reads last frame's (valid only when it was written, at
  // this output extent, and the trace history is usable too). Same ping-pong indices.
  bool upsampleTemporally = false;
  bool useOutputHistory = false;
  // Nothing moved since last frame (camera, view, projection, the clouds' wind drift): each
  // pixel's history is where it was, and the passes read it in place without reprojecting.
  bool still = false;
  // The clouds' look moved since the history's frame, within the tolerance that keeps it (a
  // weather state easing). Then the frame's fresh samples are marched this many frames ahead
  // of the change (TemporalState::marchedSettings()).
  bool cloudsChanging = false;
  float lookLeadFrames = 0.0f;
  glm::dvec3 cameraDelta{0.0};  // camera position now minus the history's (m)
  glm::dvec2 windDrift{0.0};    // how far the wind carried the clouds since (x, z m)
  // How long ago (s of FrameInputs::timeSeconds) the history's frame was: a superstorm turned
  // its clouds through this much since (cloud_vortex.h).
  double secondsSinceHistory = 0.0;
  // The view and projection the history was made with (this frame's when there is none).
  glm::mat4 previousView{1.0f};
  glm::mat4 previousProjection{1.0f};
};

// Tile offset of the n-th refresh in a k x k tile: the Bayer order, so consecutive frames
// refresh pixels far apart (k a power of two: 1, 2, 4 or 8).
glm::uvec2 tilePhase(std::uint32_t k, std::uint32_t n);

// The tile side k of an update interval (k * k = interval).
constexpr std::uint32_t tileSizeFor(std::uint32_t updateInterval) {
  std::uint32_t k = 1;
  while (k * k < updateInterval) k *= 2;
  return k;
}

// True when `a` and `b` render visibly different clouds: a field setting_effects.h marks as
// resetting the history differs by more than 1% (a flag, count or choice at all).
bool cloudsLookDifferent(const Settings& a, const Settings& b);

class TemporalState {
 public:
  // Decides this frame; call commit() once its commands are recorded. `inHeroCloud`: the
  // camera is in or near a hero cloud's box (cameraInHeroCloudBox()); `nearHeroCloud`: within
  // Settings::nearFieldMetres of one.
  TemporalFrame plan(const FrameInputs& inputs, const Settings& settings, VkExtent2D traceExtent,
                     bool inHeroCloud = false, bool nearHeroCloud = false);
  void commit(const TemporalFrame& frame, const FrameInputs& inputs, const Settings& settings,
              VkExtent2D traceExtent);
  // The settings this frame's rays are marched with: `settings`, and while the clouds' look
  // changes (frame.cloudsChanging) a weather state's look fields (clouds/weather.h: coverage,
  // type, density, anvils, erosion, skew; not the wind, which the reprojection follows) led by
  // frame.lookLeadFrames of their change since the history's frame, within their ranges.
  //
  // Why: a pixel's value is a fresh sample blended into its history every k x k frames, so a
  // look that eases is shown late, by (1 - w) / w x k^2 frames at a refresh (w the fresh
  // weight) plus the (k^2 - 1) / 2 frames a pixel waits for its next one on average: 18 frames
  // at High, 0.6 s, 5 dB against the Reference halfway through a 20 s change from Sparse to
  // Stormy (measured at Medium when it upsampled temporally). Marched that far ahead, a steady
  // change is shown on time on average; the error left
  // is the spread of the ages, a quarter of the lag. (Blending the history towards this frame's
  // sparse fresh estimate instead cost 5 to 10 dB: the history's detail is worth more.)
  Settings marchedSettings(const Settings& settings, const TemporalFrame& frame) const;
  // This frame's weather regions as marched: FrameInputs::weatherRegions with their looks led
  // as marchedSettings() leads the settings' (valid until the next call).
  std::span<const WeatherRegion> marchedRegions(const FrameInputs& in, const TemporalFrame& frame);
  // Tests: the look marched as it is, without the lead.
  void leadTheLook(bool on) { leadTheLook_ = on; }

  // The history is gone (nothing was marched, or its images were replaced): the next frame
  // starts afresh and reports `reason` (static storage).
  void forget(const char* reason) {
    havePrevious_ = false;
    forgotten_ = reason;
  }

 private:
  bool leadTheLook_ = true;
  bool havePrevious_ = false;
  const char* forgotten_ = "first frame";  // why there is no history, while there is none
  std::uint32_t temporalIndex_ = 0;
  std::uint32_t latestHistory_ = 0;  // which of the two history images holds the last result
  VkExtent2D traceExtent_{0, 0};
  VkExtent2D outputExtent_{0, 0};
  bool wroteOutputHistory_ = false;
  bool nearField_ = false;  // the history holds the far part only
  glm::dvec3 cameraPosition_{0.0};
  glm::mat4 view_{1.0f};
  glm::mat4 projection_{1.0f};
  glm::vec3 sunDirection_{0.0f, 1.0f, 0.0f};
  glm::vec3 sunIlluminance_{0.0f};
  glm::dvec2 windDisplacement_{0.0};
  double timeSeconds_ = 0.0;  // FrameInputs::timeSeconds of the history's frame
  Settings settings_{};
  PaintedWeather painted_;
  std::vector<WeatherRegion> regions_;         // the history's frame's
  std::vector<WeatherRegion> marchedRegions_;  // marchedRegions()'s
};

}  // namespace clouds::detail
