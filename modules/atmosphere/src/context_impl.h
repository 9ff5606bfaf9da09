#pragma once
// The atmosphere module's implementation behind atmosphere::Context, and the internal
// interface its tests reach through detail::ContextAccess (context_access.h).
//
// A frame: [the parameters changed: transmittance LUT -> multiple-scattering LUT] -> sky-view
// LUT and aerial-perspective froxels -> the sky-radiance map and its measurement; then, when
// the host calls render(), the sky and the aerial perspective over its colour.
//
// Where the code lives:
//   context.cpp        the public API: argument checks, error codes
//   context_impl.cpp   creation, prepare(), images, reports
//   record.cpp         recording dispatch() and render()
//   uniforms.cpp       the per-frame uniform block
//   programs.cpp       the pass table
//   parameters.cpp     validation, presets, the CPU sun transmittance
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "atmosphere/atmosphere.h"
#include "atmosphere_types.h"
#include "kit.h"
#include "programs.h"
#include "sky_draw.h"

namespace atmosphere {

class Context::Impl {
 public:
  // Throws vkfx::Error when something cannot be created; what was created is destroyed.
  Impl(const CreateInfo& info, const detail::VulkanFunctions& functions);

  // Throws vkfx::Error (OutOfMemory, VulkanFailure).
  void prepare(const Parameters& parameters, const Settings& settings);
  // Empty when dispatch() can run these, else what prepare() must make.
  std::string unprepared(const Parameters& parameters, const Settings& settings) const;
  // Inputs, parameters and settings are valid and prepared (context.cpp checks).
  void dispatch(const FrameInputs& inputs, const Parameters& parameters, const Settings& settings);
  void render(VkCommandBuffer cmd, VkImageView color, VkImageView depth, VkImageLayout layout);
  void drawSky(VkCommandBuffer cmd);
  bool drawsSky() const { return skyDraw_ != nullptr; }

  Outputs outputs() const;
  SkyLighting skyLighting(std::uint64_t frameIndex) const;
  MemoryUsage memoryUsage() const;
  std::vector<PassTiming> passTimings(std::uint64_t frameIndex) const;
  const CreateInfo& createInfo() const { return info_; }
  // The render extent of the last dispatch (render() must use it).
  VkExtent2D lastExtent() const { return lastExtent_; }
  bool dispatched() const { return lastFrameIndex_.has_value(); }

  // --- Internal access (tests) ------------------------------------------------------------
  const detail::DeviceContext& device() const { return device_; }
  const shader::AtmosphereUniforms& lastUniforms() const { return lastUniforms_; }
  const detail::OwnedImage& transmittanceLut() const { return transmittance_; }
  const detail::OwnedImage& multiScatteringLut() const { return multiScattering_; }
  const detail::OwnedImage& skyViewLut() const { return skyView_; }
  const detail::OwnedImage& aerialPerspective() const { return aerialPerspective_; }
  const detail::OwnedImage& environment() const { return environment_; }
  // How many times the parameter-only LUTs were recorded (tests: not every frame).
  std::uint64_t lutBuilds() const { return lutBuilds_; }
  // How many times the sky-view LUT was recorded (tests: only when the camera's altitude or the
  // sun moved).
  std::uint64_t skyViewBuilds() const { return skyViewBuilds_; }

 private:
  static constexpr std::size_t kPrograms = static_cast<std::size_t>(detail::Program::Count);
  struct Slot {
    detail::OwnedBuffer uniforms;
    detail::OwnedBuffer cloudShadow;  // FrameInputs::cloudShadow's parameters
    detail::OwnedBuffer lighting;     // host-visible SkyLighting
    std::optional<std::uint64_t> lightingFrame;
    std::array<VkDescriptorSet, kPrograms> sets{};
    VkDescriptorSet skyDrawSet = VK_NULL_HANDLE;  // with CreateInfo::skyPassColorFormat
  };
  struct Retired {
    detail::OwnedImage image;
    std::optional<std::uint64_t> lastUse;
  };

  VkDescriptorSet allocateSet(VkDescriptorSetLayout layout);
  detail::OwnedImage makeImage(VkImageType type, VkExtent3D extent, const std::string& name);
  void replace(detail::OwnedImage& slot, detail::OwnedImage replacement);
  void releaseRetired(std::uint64_t frameIndex);
  void beginPass(VkCommandBuffer cmd, detail::Program program);
  void endPass(VkCommandBuffer cmd, detail::Program program);
  void pushUniformsIndex(VkCommandBuffer cmd, VkPipelineLayout layout);
  void bindAndDispatch(VkCommandBuffer cmd, detail::Program program, const Slot& slot,
                       std::uint32_t x, std::uint32_t y, std::uint32_t z = 1);
  // Whether the sky-view LUT as last built serves a camera at `altitudeMetres` under this frame's
  // sun (skyViewBuild_).
  bool skyViewServes(double altitudeMetres, const Settings& settings) const;
  // `shadow`: the frame's cloud shadow (dispatch(); render() passes none and keeps it).
  void writeSets(Slot& slot, VkImageView depth, VkImageLayout depthLayout, VkImageView color,
                 const FrameInputs::CloudShadow* shadow = nullptr);

  // Declaration order is destruction order reversed: everything below uses device_.
  CreateInfo info_;
  detail::DeviceContext device_;
  detail::Programs programs_;
  std::unique_ptr<detail::SkyDraw> skyDraw_;  // drawSky(), when the host asked for it
  detail::UniqueSampler linearSampler_;
  detail::UniqueSampler nearestSampler_;
  detail::UniqueDescriptorPool pool_;
  std::unique_ptr<detail::PassTimer> timer_;
  std::vector<Slot> slots_;

  detail::OwnedImage transmittance_;
  detail::OwnedImage multiScattering_;
  detail::OwnedImage skyView_;
  detail::OwnedImage aerialPerspective_;
  detail::OwnedImage environment_;
  detail::OwnedImage depthPlaceholder_;  // 1 x 1 sampled: render() without a depth view
  std::vector<VkImage> pendingLayouts_;  // made since the last dispatch: UNDEFINED -> GENERAL
  std::vector<Retired> retired_;

  std::optional<Settings> sizedFor_;       // the settings the images have
  std::optional<Parameters> preparedFor_;  // the parameters the next LUT build uses
  bool lutsDirty_ = true;
  std::uint64_t lutBuilds_ = 0;
  // What the sky-view LUT was last built for, of what changes from frame to frame; none when
  // prepare() changed the rest (its image, its samples, the LUTs it reads).
  struct SkyViewBuild {
    double altitudeMetres = 0.0;  // the camera's, at least 1 m (uniforms.cpp)
    float sunHeight = 0.0f;       // the unit sun direction's y: its elevation's sine
  };
  std::optional<SkyViewBuild> skyViewBuild_;
  std::uint64_t skyViewBuilds_ = 0;
  std::optional<std::uint64_t> lastFrameIndex_;
  std::uint32_t lastSlot_ = 0;
  VkExtent2D lastExtent_{0, 0};
  shader::AtmosphereUniforms lastUniforms_{};
};

}  // namespace atmosphere
