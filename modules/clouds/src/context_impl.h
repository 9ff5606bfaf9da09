#pragma once
// The module's implementation behind clouds::Context. Also the internal interface the module's
// own tests and tools use (noise textures, weather map, last uniforms, debug flags).
//
// A frame: [first: noise generation] -> weather map and its maxima (when due) -> uniforms ->
// [sky ambient] -> conservative scene distance at trace resolution -> march (one pixel per
// tile) -> temporal reconstruction -> depth-aware upsample into the outputs.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "cloud_types.h"
#include "clouds/clouds.h"
#include "compute_program.h"
#include "device_context.h"
#include "pass_timer.h"
#include "temporal_state.h"
#include "uniforms.h"
#include "weather_schedule.h"

namespace clouds {

class Context::Impl {
 public:
  Impl(const CreateInfo& info, const detail::VulkanFunctions& functions);
  ~Impl();

  void dispatch(const FrameInputs& inputs, const Settings& settings);
  void composite(VkCommandBuffer cmd, VkImageView color, VkExtent2D extent);
  Outputs outputs() const;
  FrameReport lastFrameReport() const { return report_; }
  WorkCounters workCounters(std::uint64_t frameIndex) const;
  std::vector<PassTiming> passTimings(std::uint64_t frameIndex) const;

  // --- Internal access (tests, tools) --------------------------------------------------
  const detail::DeviceContext& device() const { return device_; }
  const detail::OwnedImage& shapeNoise() const { return shapeNoise_; }
  const detail::OwnedImage& detailNoise() const { return detailNoise_; }
  const detail::OwnedImage& curlNoise() const { return curlNoise_; }
  // The weather map in use (the other one is being prepared for the next period).
  const detail::OwnedImage& weatherMap() const { return weatherMaps_[currentWeather_]; }
  const detail::OwnedImage& weatherMaxFine() const { return weatherMaxFine_; }
  const detail::OwnedImage& history(std::uint32_t i) const { return history_[i]; }
  const detail::OwnedImage& outputHistory(std::uint32_t i) const { return outputHistory_[i]; }
  const shader::CloudUniforms& lastUniforms() const { return lastUniforms_; }
  const CreateInfo& createInfo() const { return info_; }
  std::size_t pipelineVariantCount() const { return march_->variantCount(); }
  std::uint64_t weatherUpdates() const { return weatherUpdates_; }
  // Test-only uniform flags (e.g. shader::kFlagHomogeneous) ORed into every frame.
  void setDebugFlags(std::uint32_t flags) { debugFlags_ = flags; }

 private:
  struct Slot {
    detail::OwnedBuffer uniforms;
    detail::OwnedBuffer counters;  // host-visible, CreateInfo::workCounters
    VkDescriptorSet downsample = VK_NULL_HANDLE;
    VkDescriptorSet march = VK_NULL_HANDLE;
    VkDescriptorSet reconstruct = VK_NULL_HANDLE;
    VkDescriptorSet upsample = VK_NULL_HANDLE;
    VkDescriptorSet composite = VK_NULL_HANDLE;
    VkDescriptorSet skyAmbient = VK_NULL_HANDLE;
    VkDescriptorSet weatherResample = VK_NULL_HANDLE;
  };

  VkDescriptorSet allocateSet(VkDescriptorSetLayout layout);
  // A debug label and, with CreateInfo::passTimings, timestamps around a pass.
  void beginPass(VkCommandBuffer cmd, detail::Pass pass, const char* label);
  void endPass(VkCommandBuffer cmd, detail::Pass pass);
  void recordInitialisation(VkCommandBuffer cmd);
  void recordWeather(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                     Slot& slot);
  void recordWeatherRows(VkCommandBuffer cmd, const Settings& settings,
                         const detail::WeatherWork& work, double mapTimeSeconds);
  void recordWeatherMaxima(VkCommandBuffer cmd);
  void recordUniforms(VkCommandBuffer cmd, Slot& slot, const shader::CloudUniforms& uniforms);
  void recordSkyAmbient(VkCommandBuffer cmd, const FrameInputs& inputs, Slot& slot);
  static bool skyIsClear(const Settings& settings);
  void recordClearSky(VkCommandBuffer cmd, Slot& slot);
  void recordTrace(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                   const detail::TemporalFrame& temporal, VkExtent2D traceExtent, Slot& slot);
  void bindAndDispatch(VkCommandBuffer cmd, detail::ComputeProgram& program, VkPipeline pipeline,
                       VkDescriptorSet set, std::uint32_t width, std::uint32_t height);

  CreateInfo info_;
  detail::DeviceContext device_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkSampler nearestSampler_ = VK_NULL_HANDLE;
  VkSampler linearSampler_ = VK_NULL_HANDLE;

  detail::OwnedImage shapeNoise_;
  detail::OwnedImage detailNoise_;
  detail::OwnedImage curlNoise_;
  std::array<detail::OwnedImage, 2> weatherMaps_;  // current and spare (weather_schedule.h)
  detail::OwnedImage weatherMaxFine_;
  detail::OwnedImage weatherMaxCoarse_;
  detail::OwnedImage sceneDistance_;           // trace resolution, R32F
  detail::OwnedImage traceSamples_;            // this frame's marched pixels (packed samples)
  std::array<detail::OwnedImage, 2> history_;  // reconstructed frames, ping-pong
  // Temporal upsampling's own samples per output pixel, ping-pong with history_.
  std::array<detail::OwnedImage, 2> outputHistory_;
  detail::OwnedImage radiance_;  // outputs, output resolution
  detail::OwnedImage depth_;
  detail::OwnedImage placeholder_;  // 1x1 sampled stand-in for absent optional inputs

  std::unique_ptr<detail::ComputeProgram> shapeProgram_;
  std::unique_ptr<detail::ComputeProgram> detailProgram_;
  std::unique_ptr<detail::ComputeProgram> curlProgram_;
  std::unique_ptr<detail::ComputeProgram> weatherProgram_;
  std::unique_ptr<detail::ComputeProgram> weatherMaxProgram_;
  std::unique_ptr<detail::ComputeProgram> resampleProgram_;
  std::unique_ptr<detail::ComputeProgram> skyAmbientProgram_;
  std::unique_ptr<detail::ComputeProgram> downsample_;
  std::unique_ptr<detail::ComputeProgram> march_;
  std::unique_ptr<detail::ComputeProgram> reconstruct_;
  std::unique_ptr<detail::ComputeProgram> upsample_;
  std::unique_ptr<detail::ComputeProgram> compositeProgram_;

  VkDescriptorSet shapeSet_ = VK_NULL_HANDLE;
  VkDescriptorSet detailSet_ = VK_NULL_HANDLE;
  VkDescriptorSet curlSet_ = VK_NULL_HANDLE;
  std::array<VkDescriptorSet, 2> weatherSets_{};         // generator, per map
  std::array<VkDescriptorSet, 2> weatherMaxFineSets_{};  // map -> fine maxima, per map
  VkDescriptorSet weatherMaxCoarseSet_ = VK_NULL_HANDLE;
  std::vector<Slot> slots_;
  std::unique_ptr<detail::PassTimer> timer_;  // CreateInfo::passTimings

  bool initialised_ = false;
  detail::WeatherSchedule weatherSchedule_;
  std::uint32_t currentWeather_ = 0;  // index into weatherMaps_
  std::uint64_t weatherUpdates_ = 0;
  std::uint32_t lastSlot_ = 0;
  VkExtent2D lastExtent_{0, 0};
  detail::TemporalState temporal_;
  FrameReport report_{};
  shader::CloudUniforms lastUniforms_{};
  std::uint32_t debugFlags_ = 0;
};

}  // namespace clouds
