#pragma once
// A host for the clouds module built on engine::gfx, for the module's GPU tests, the CPU
// reference comparisons, the preview tool and the benchmark. It renders a view into
// the module's outputs, reads them back as float images, and can also read back the noise
// textures and weather map (so the CPU reference samples exactly the same texels).
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clouds/clouds.h"
#include "engine/assets/image_io.h"
#include "engine/assets/image_metrics.h"
#include "engine/gfx/device.h"
#include "engine/gfx/gpu_timer.h"
#include "engine/gfx/resources.h"

namespace clouds::detail {
class ModuleImages;
}

namespace clouds::tools {

// A camera and sun, in the conventions of the module (metres, Y up, yaw 0 looks along -Z).
struct CloudView {
  glm::dvec3 position{0.0, 300.0, 0.0};
  double yawDegrees = 0.0;     // counter-clockwise seen from above
  double pitchDegrees = 10.0;  // up is positive
  float verticalFovDegrees = 70.0f;
  // Moves every ray by this much of an output pixel, through the projection (as a host's TAA
  // jitter would): the bench's Reference takes its subpixel positions from its own sequence,
  // so that its average owes nothing to the positions the module's presets sample.
  glm::vec2 projectionJitterPixels{0.0f};
  double sunElevationDegrees = 35.0;
  double sunAzimuthDegrees = 200.0;  // 0 = towards -Z, counter-clockwise
  glm::vec3 sunIlluminance{10.0f, 9.6f, 9.0f};
  glm::vec3 ambientTop{0.35f, 0.5f, 0.85f};
  glm::vec3 ambientBottom{0.25f, 0.27f, 0.3f};
  // Optional ground albedo (FrameInputs::groundAlbedo); with it render() also records the shadow
  // map before each frame, whose shade on the ground dims the light cloud bases get from it.
  std::optional<glm::vec3> groundAlbedo;
  bool groundDepth = false;  // a flat ground at y = 0 in the host depth buffer
  // Optional host depth values instead (reversed-Z, one a pixel, rows top to bottom); the
  // extent rendered must match.
  std::vector<float> hostDepth;
  double timeSeconds = 0.0;
  // Where the wind has carried the clouds (FrameInputs::windDisplacementMetres); none: the
  // time x the settings' wind.
  std::optional<glm::dvec2> windDisplacementMetres;
  // Optional host images (sampled, SHADER_READ_ONLY_OPTIMAL): painted weather, sky radiance.
  VkImageView weatherView = VK_NULL_HANDLE;
  VkImageView weatherBlendView = VK_NULL_HANDLE;  // FrameInputs::weatherBlendView
  float weatherBlend = 0.0f;                      //   and weatherBlend
  VkImageView skyView = VK_NULL_HANDLE;
  // Optional haze (FrameInputs::aerialPerspective), its view sampled in SHADER_READ_ONLY_OPTIMAL.
  clouds::FrameInputs::AerialPerspective aerialPerspective;
  // Optional terrain heightfield (FrameInputs::terrain); with it render() also records the
  // shadow map before each frame, as the terrain's shadow on the clouds needs.
  clouds::FrameInputs::Terrain terrain;
  // This frame's lightning flashes (FrameInputs::lightningFlashes).
  std::vector<clouds::LightningFlash> lightningFlashes;
  // This frame's lightning bolts (FrameInputs::lightningBolts).
  std::vector<clouds::LightningBoltSegment> lightningBolts;
  // This frame's hero clouds (FrameInputs::heroClouds), of the assets given to the harness's
  // context (Context::setHeroCloudAssets()).
  std::vector<clouds::HeroCloud> heroClouds;
  // This frame's weather regions (FrameInputs::weatherRegions).
  std::vector<clouds::WeatherRegion> weatherRegions;
};

glm::vec3 sunDirection(const CloudView& view);
glm::vec3 forwardDirection(const CloudView& view);
glm::mat4 viewMatrix(const CloudView& view);
glm::mat4 projectionMatrix(const CloudView& view, VkExtent2D extent);

// The directions (world, camera-relative, unit) of the rays through pixel centres, y down:
// what the module marches for `view` at `extent`. Built once per image.
class PixelRays {
 public:
  PixelRays(const CloudView& view, VkExtent2D extent);
  glm::vec3 direction(std::uint32_t x, std::uint32_t y) const;

 private:
  glm::mat4 inverseProjection_;
  glm::mat3 viewToWorld_;
  VkExtent2D extent_;
};

struct CloudFrame {
  VkExtent2D extent{};
  std::vector<glm::vec4> radiance;  // rgb radiance, a transmittance
  std::vector<glm::vec2> depth;     // front depth, weighted depth (m); none without the output
};

// The cloud shadow map as read back (Outputs::shadowMap): texels (optical depth, highest and
// lowest cloud altitude, terrain shadow altitude), row-major, and where its cascades lay.
struct ShadowMapImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<glm::vec4> texels;
  clouds::ShadowMapParameters parameters;
  // The receivers' lookup (fxcontracts/cloud_shadow.h) on these texels, filtered as a linear
  // clamped sampler filters, at a camera-relative position: the clouds' transmittance towards the
  // sun (x) and the light the terrain lets through (y).
  glm::vec2 lookup(const glm::vec3& relative) const;
  float transmittance(const glm::vec3& relative) const { return lookup(relative).x; }
  float terrainLight(const glm::vec3& relative) const { return lookup(relative).y; }
};

// The god-ray occlusion image and mask as read back (fxcontracts/god_rays.h), row-major, with the
// parameters of the frame that made them (Outputs::godRaySun, godRayBlur).
struct GodRayImages {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> occlusion;
  std::vector<float> mask;
  glm::vec4 sun{0.0f};
  glm::vec4 blur{0.0f};
  // The occlusion image filtered as a linear, clamped sampler filters it, at a mask uv.
  float occlusionAt(glm::vec2 uv) const;
};

// The sky light as read back (Outputs::skyLight): texels (radiance, 1) row-major, v = 0 at the
// zenith, and the last frame's measures (Context::skyLighting()).
struct SkyLightImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<glm::vec4> texels;
  clouds::SkyLighting measures;
  const glm::vec4& at(std::uint32_t x, std::uint32_t y) const {
    return texels[std::size_t{y} * width + x];
  }
};

// `settings` rendered as one self-contained frame: every pixel marched at full resolution, no
// history. What the CPU reference computes, and what analytic tests compare against.
clouds::Settings singleFrame(clouds::Settings settings);

struct HarnessOptions {
  std::uint32_t noiseSeed = 1;
  bool workCounters = false;  // CreateInfo::workCounters
  bool passTimings = false;   // CreateInfo::passTimings
};

class CloudHarness {
 public:
  CloudHarness(engine::gfx::Device& device, VkExtent2D maxExtent, HarnessOptions options = {});
  ~CloudHarness();

  // Renders `frames` frames of `view` and returns the last one. Frames form one sequence
  // across calls, as a game's would (the module remembers the previous camera), and only the
  // first frame (or the one after cut()) is a camera cut. Each frame prepares the settings
  // outside recording first. Throws engine::Error when the module rejects the inputs.
  CloudFrame render(const CloudView& view, const clouds::Settings& settings, VkExtent2D extent,
                    std::uint32_t frames = 1);
  // The mean of `frames` frames of `view` rendered after a cut. With the Reference mode's
  // jitter (rays move inside their pixels frame to frame) this is a converged, supersampled
  // image: the ground truth of the accuracy measurements.
  CloudFrame renderAveraged(const CloudView& view, const clouds::Settings& settings,
                            VkExtent2D extent, std::uint32_t frames);
  // Prepares and records one frame, returning the module's error message instead of throwing.
  std::string tryRender(const CloudView& view, const clouds::Settings& settings, VkExtent2D extent);

  // Records `frames` frames of dispatchShadowMap() alone for `view` (each a frame of the
  // sequence) and reads the shadow map back. Throws engine::Error when the module refuses.
  ShadowMapImage renderShadowMap(const CloudView& view, const clouds::Settings& settings,
                                 std::uint32_t frames = 1);
  ShadowMapImage readShadowMap();
  // The last dispatch()'s sky light (empty without one).
  SkyLightImage readSkyLight();
  // The last dispatch()'s god-ray images (empty without god rays).
  GodRayImages readGodRays();

  // Marks the next frame as a camera cut (FrameInputs::reset).
  void cut() { cutNext_ = true; }
  // Overwrites the temporal history images (trace and output resolution) with NaN (tests:
  // poisoned history must not leak).
  void poisonHistory();
  // Fills the radiance output with `value`: a mark that tells a test, reading it back after a
  // frame, whether that frame wrote the output.
  void markRadianceOutput(glm::vec4 value);
  // The work counters and pass times of the last rendered frame (zeros / empty unless
  // created with workCounters / passTimings).
  clouds::WorkCounters lastWorkCounters() const;
  std::vector<clouds::PassTiming> lastPassTimings() const;

  clouds::Context& context() { return *context_; }
  clouds::MemoryUsage memoryUsage() const { return context_->memoryUsage(); }
  // The module's images (internal access, context_access.h).
  const clouds::detail::ModuleImages& moduleImages() const;
  // The host depth values of the last render with groundDepth (reversed-Z), else empty.
  const std::vector<float>& lastDepth() const { return depthValues_; }
  const clouds::FrameInputs& lastInputs() const { return lastInputs_; }
  // GPU time of the module's work in the last render's final frame (timestamps), in ms.
  double lastGpuMilliseconds() const { return lastGpuMilliseconds_; }

  // Read-backs of the module's textures as RGBA8 texels (valid after a render).
  std::vector<std::uint8_t> readShapeNoise();
  // The hero clouds' detail noise chain (kHeroNoiseSize x kHeroNoiseSize x kHeroNoiseDepth
  // RGBA8); empty when the context has not made it.
  std::vector<std::uint8_t> readHeroNoise();
  std::vector<std::uint8_t> readDetailNoise();
  std::vector<std::uint8_t> readCurlNoise();
  std::vector<std::uint8_t> readWeatherMap();
  std::vector<std::uint8_t> readWeatherMaxFine();

 private:
  void prepareDepth(const CloudView& view, VkExtent2D extent);
  clouds::FrameInputs makeInputs(const CloudView& view, VkExtent2D extent, VkCommandBuffer cmd);

  engine::gfx::Device& device_;
  std::unique_ptr<clouds::Context> context_;
  engine::gfx::Image depth_;
  std::vector<float> depthValues_;
  std::uint64_t frameIndex_ = 0;
  bool cutNext_ = true;
  std::unique_ptr<engine::gfx::GpuTimer> timer_;
  double lastGpuMilliseconds_ = 0.0;
  clouds::FrameInputs lastInputs_{};
};

// Display helpers: the clouds composited over a plain sky gradient (and dark ground below the
// horizon), tonemapped, in sRGB [0, 1] per channel; and that as an 8-bit image.
std::vector<glm::vec3> tonemappedPixels(const CloudFrame& frame, const CloudView& view,
                                        float exposure = 1.0f);
engine::assets::ImageRgba8 previewImage(const CloudFrame& frame, const CloudView& view,
                                        float exposure = 1.0f);

// Error of an image against a reference, both as tonemappedPixels() (values in [0, 1]); and the
// PSNR of two radiance frames over all four channels. Thin adapters to
// engine/assets/image_metrics.h.
engine::assets::ImageError imageError(const std::vector<glm::vec3>& image,
                                      const std::vector<glm::vec3>& reference);
double psnr(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b, double peak);

}  // namespace clouds::tools
