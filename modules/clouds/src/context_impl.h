#pragma once
// The module's implementation behind clouds::Context. Also the internal interface the module's
// own tests and tools use (noise textures, the weather map, the last uniforms).
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "clouds/clouds.h"
#include "cloud_types.h"
#include "compute_program.h"
#include "device_context.h"
#include "uniforms.h"

namespace clouds {

class Context::Impl {
 public:
  Impl(const CreateInfo& info, const detail::VulkanFunctions& functions);
  ~Impl();

  void dispatch(const FrameInputs& inputs, const Settings& settings);
  void composite(VkCommandBuffer cmd, VkImageView color, VkExtent2D extent);
  Outputs outputs() const;

  // --- Internal access (tests, tools) --------------------------------------------------
  const detail::DeviceContext& device() const { return device_; }
  const detail::OwnedImage& shapeNoise() const { return shapeNoise_; }
  const detail::OwnedImage& detailNoise() const { return detailNoise_; }
  const detail::OwnedImage& curlNoise() const { return curlNoise_; }
  const detail::OwnedImage& weatherMap() const { return weatherMap_; }
  const shader::CloudUniforms& lastUniforms() const { return lastUniforms_; }
  const CreateInfo& createInfo() const { return info_; }
  std::size_t pipelineVariantCount() const { return march_->variantCount(); }
  // How many times the weather map has been (re)generated or resampled.
  std::uint64_t weatherUpdates() const { return weatherUpdates_; }
  // Test-only uniform flags (e.g. shader::kFlagHomogeneous) ORed into every frame.
  void setDebugFlags(std::uint32_t flags) { debugFlags_ = flags; }

 private:
  struct Slot {
    detail::OwnedBuffer uniforms;
    VkDescriptorSet march = VK_NULL_HANDLE;
    VkDescriptorSet composite = VK_NULL_HANDLE;
    VkDescriptorSet skyAmbient = VK_NULL_HANDLE;
    VkDescriptorSet weatherResample = VK_NULL_HANDLE;
  };

  VkDescriptorSet allocateSet(VkDescriptorSetLayout layout);
  void recordInitialisation(VkCommandBuffer cmd);
  void recordWeather(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                     Slot& slot);
  void recordUniforms(VkCommandBuffer cmd, Slot& slot, const shader::CloudUniforms& uniforms);
  void recordSkyAmbient(VkCommandBuffer cmd, const FrameInputs& inputs, Slot& slot);
  void recordMarch(VkCommandBuffer cmd, const FrameInputs& inputs, const Settings& settings,
                   Slot& slot);

  CreateInfo info_;
  detail::DeviceContext device_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkSampler nearestSampler_ = VK_NULL_HANDLE;
  VkSampler linearSampler_ = VK_NULL_HANDLE;

  detail::OwnedImage shapeNoise_;
  detail::OwnedImage detailNoise_;
  detail::OwnedImage curlNoise_;
  detail::OwnedImage weatherMap_;
  detail::OwnedImage radiance_;
  detail::OwnedImage depth_;
  detail::OwnedImage placeholder_;  // 1x1 sampled stand-in for absent optional inputs

  std::unique_ptr<detail::ComputeProgram> shapeProgram_;
  std::unique_ptr<detail::ComputeProgram> detailProgram_;
  std::unique_ptr<detail::ComputeProgram> curlProgram_;
  std::unique_ptr<detail::ComputeProgram> weatherProgram_;
  std::unique_ptr<detail::ComputeProgram> resampleProgram_;
  std::unique_ptr<detail::ComputeProgram> skyAmbientProgram_;
  std::unique_ptr<detail::ComputeProgram> march_;
  std::unique_ptr<detail::ComputeProgram> compositeProgram_;

  VkDescriptorSet shapeSet_ = VK_NULL_HANDLE;
  VkDescriptorSet detailSet_ = VK_NULL_HANDLE;
  VkDescriptorSet curlSet_ = VK_NULL_HANDLE;
  VkDescriptorSet weatherSet_ = VK_NULL_HANDLE;
  std::vector<Slot> slots_;

  bool initialised_ = false;
  std::optional<std::int64_t> weatherKey_;  // time bucket of the procedural map
  std::uint64_t weatherUpdates_ = 0;
  std::uint32_t lastSlot_ = 0;
  VkExtent2D lastExtent_{0, 0};
  shader::CloudUniforms lastUniforms_{};
  std::uint32_t debugFlags_ = 0;
};

}  // namespace clouds
