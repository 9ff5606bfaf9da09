#pragma once
// A host for the clouds module built on engine::gfx, for the module's GPU tests, the CPU
// reference comparisons, look-development previews and the benchmark. It renders a view into
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
#include "engine/gfx/device.h"
#include "engine/gfx/gpu_timer.h"
#include "engine/gfx/resources.h"

namespace test {

// A camera and sun, in the conventions of the module (metres, Y up, yaw 0 looks along -Z).
struct CloudView {
  glm::dvec3 position{0.0, 300.0, 0.0};
  double yawDegrees = 0.0;     // counter-clockwise seen from above
  double pitchDegrees = 10.0;  // up is positive
  float verticalFovDegrees = 70.0f;
  double sunElevationDegrees = 35.0;
  double sunAzimuthDegrees = 200.0;  // 0 = towards -Z, counter-clockwise
  glm::vec3 sunIlluminance{10.0f, 9.6f, 9.0f};
  glm::vec3 ambientTop{0.35f, 0.5f, 0.85f};
  glm::vec3 ambientBottom{0.25f, 0.27f, 0.3f};
  bool groundDepth = false;  // a flat ground at y = 0 in the host depth buffer
  double timeSeconds = 0.0;
  // Optional host images (sampled, SHADER_READ_ONLY_OPTIMAL): painted weather, sky radiance.
  VkImageView weatherView = VK_NULL_HANDLE;
  VkImageView skyView = VK_NULL_HANDLE;
};

glm::vec3 sunDirection(const CloudView& view);
glm::vec3 forwardDirection(const CloudView& view);
glm::mat4 viewMatrix(const CloudView& view);
glm::mat4 projectionMatrix(const CloudView& view, VkExtent2D extent);

struct CloudFrame {
  VkExtent2D extent{};
  std::vector<glm::vec4> radiance;  // rgb radiance, a transmittance
  std::vector<glm::vec2> depth;     // front depth, weighted depth (m)
};

class CloudHarness {
 public:
  CloudHarness(engine::gfx::Device& device, VkExtent2D maxExtent, std::uint32_t noiseSeed = 1);
  ~CloudHarness();

  // Renders `frames` frames of `view` (frame indices continue across calls unless reset) and
  // returns the last one. Throws engine::Error when the module rejects the inputs.
  CloudFrame render(const CloudView& view, const clouds::Settings& settings, VkExtent2D extent,
                    std::uint32_t frames = 1);
  // Records one frame, returning the module's error message instead of throwing.
  std::string tryRender(const CloudView& view, const clouds::Settings& settings, VkExtent2D extent);

  clouds::Context& context() { return *context_; }
  // The host depth values of the last render with groundDepth (reversed-Z), else empty.
  const std::vector<float>& lastDepth() const { return depthValues_; }
  const clouds::FrameInputs& lastInputs() const { return lastInputs_; }
  // GPU time of the module's work in the last render's final frame (timestamps), in ms.
  double lastGpuMilliseconds() const { return lastGpuMilliseconds_; }

  // Read-backs of the module's textures as RGBA8 texels (valid after a render).
  std::vector<std::uint8_t> readShapeNoise();
  std::vector<std::uint8_t> readDetailNoise();
  std::vector<std::uint8_t> readCurlNoise();
  std::vector<std::uint8_t> readWeatherMap();

 private:
  void prepareDepth(const CloudView& view, VkExtent2D extent);
  clouds::FrameInputs makeInputs(const CloudView& view, VkExtent2D extent, VkCommandBuffer cmd);

  engine::gfx::Device& device_;
  std::unique_ptr<clouds::Context> context_;
  engine::gfx::Image depth_;
  std::vector<float> depthValues_;
  std::uint64_t frameIndex_ = 0;
  std::unique_ptr<engine::gfx::GpuTimer> timer_;
  double lastGpuMilliseconds_ = 0.0;
  clouds::FrameInputs lastInputs_{};
};

// Display helpers: composite over a plain sky gradient, tonemap, write PNG.
engine::assets::ImageRgba8 previewImage(const CloudFrame& frame, const CloudView& view,
                                        float exposure = 1.0f);
double psnr(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b, double peak);

}  // namespace test
