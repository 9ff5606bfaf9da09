#pragma once
// A host for the atmosphere module built on engine::gfx, for the module's GPU tests and the
// benchmark: it renders a view (the sky over a flat ground the host "drew" in one colour),
// and reads back the module's LUTs, froxels, sky map and measurement as float images.
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "atmosphere/atmosphere.h"
#include "engine/gfx/device.h"
#include "engine/gfx/gpu_timer.h"
#include "engine/gfx/resources.h"

namespace atmosphere::tools {

// A camera and sun (metres, Y up; yaw and azimuth 0 along -Z, counter-clockwise from above).
struct SkyView {
  glm::dvec3 position{0.0, 300.0, 0.0};
  double yawDegrees = 0.0;
  double pitchDegrees = 10.0;  // up is positive
  float verticalFovDegrees = 70.0f;
  double sunElevationDegrees = 35.0;
  double sunAzimuthDegrees = 200.0;
  glm::vec3 sunIlluminance{1.0f};  // at the top of the atmosphere
  // A flat ground at y = 0 in the host's depth, drawn in `groundColour` (radiance) before the
  // module hazes it; without it every pixel is sky.
  bool groundDepth = false;
  glm::vec3 groundColour{0.0f};
  // Optional shadow of the sun in the air (FrameInputs::cloudShadow).
  FrameInputs::CloudShadow cloudShadow;
};

glm::vec3 sunDirection(const SkyView& view);
glm::mat4 viewMatrix(const SkyView& view);
glm::mat4 projectionMatrix(const SkyView& view, VkExtent2D extent);

// An image read back as floats: rgba per texel, x fastest, then y, then z.
struct FloatImage {
  VkExtent3D extent{0, 0, 0};
  std::vector<glm::vec4> texels;
  const glm::vec4& at(std::uint32_t x, std::uint32_t y, std::uint32_t z = 0) const {
    return texels[(std::size_t{z} * extent.height + y) * extent.width + x];
  }
};

class AtmosphereHarness {
 public:
  AtmosphereHarness(engine::gfx::Device& device, VkExtent2D maxExtent, bool passTimings = false);
  ~AtmosphereHarness();

  // Prepares (outside recording), records dispatch() and render() over the host's colour, and
  // returns the colour. Frames form one sequence across calls. Throws engine::Error when the
  // module rejects the inputs.
  FloatImage render(const SkyView& view, const Parameters& parameters, const Settings& settings,
                    VkExtent2D extent);
  // The same, returning the module's error message instead of throwing.
  std::string tryRender(const SkyView& view, const Parameters& parameters, const Settings& settings,
                        VkExtent2D extent);

  // The same frame drawn the other way: dispatch(), then drawSky() inside a dynamic-rendering
  // pass over the host's colour (the ground, unhazed) and its depth, as a host's scene pass
  // draws it after its geometry.
  FloatImage drawSky(const SkyView& view, const Parameters& parameters, const Settings& settings,
                     VkExtent2D extent);
  // The module's outputs after the last render.
  FloatImage read(const OutputImage& output);
  FloatImage readTransmittance() { return read(context_->outputs().transmittance); }
  FloatImage readMultiScattering() { return read(context_->outputs().multipleScattering); }
  FloatImage readSkyView() { return read(context_->outputs().skyView); }
  FloatImage readAerialPerspective() { return read(context_->outputs().aerialPerspective); }
  FloatImage readEnvironment() { return read(context_->outputs().environment); }
  SkyLighting lastSkyLighting() const;
  std::vector<PassTiming> lastPassTimings() const;
  // GPU time of the last frame's dispatch() and render() together (timestamps), in ms.
  double lastGpuMilliseconds() const { return lastGpuMilliseconds_; }

  Context& context() { return *context_; }

 private:
  void prepareHostImages(const SkyView& view, VkExtent2D extent);
  // Prepares and records dispatch() and then `draw` (render() or drawSky()); the error message.
  template <typename Draw>
  std::string record(const SkyView& view, const Parameters& parameters, const Settings& settings,
                     VkExtent2D extent, Draw&& draw);

  engine::gfx::Device& device_;
  std::unique_ptr<Context> context_;
  engine::gfx::Image colour_;
  engine::gfx::Image depth_;
  std::unique_ptr<engine::gfx::GpuTimer> timer_;
  std::uint64_t frameIndex_ = 0;
  double lastGpuMilliseconds_ = 0.0;
};

// PSNR (dB) of `image` against `reference` over the rgb channels, with the reference's largest
// channel value as the peak (LUTs hold radiances and transmittances of any scale).
double psnrRgb(const std::vector<glm::dvec3>& image, const std::vector<glm::dvec3>& reference);

}  // namespace atmosphere::tools
