// Recording the god-ray mask (vkfx/god_rays.h) after the clouds' outputs are made: the
// occlusion image (the clouds' transmittance where the host's depth is sky), then its radial
// blur towards the sun; with the sun far off screen, behind the camera or set, only a clear of
// the mask to 1. And the god-ray half of the composite helper: its uniforms and descriptors.
#include "context_impl.h"
#include "god_rays.h"
#include "kit.h"

namespace clouds {
namespace {

using detail::kStorageRead;
using detail::kStorageWrite;
using detail::Program;
constexpr VkPipelineStageFlags2 kCompute = detail::kComputeStage;
constexpr VkPipelineStageFlags2 kHostReadStages =
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkAccessFlags2 kHostReadAccess =
    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
constexpr VkAccessFlags2 kSampledRead = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;

std::uint32_t groups(std::uint32_t n) {
  return detail::groupsFor(n, shader::kWorkgroupSize2D);
}

}  // namespace

void Context::Impl::recordGodRays(VkCommandBuffer cmd, const FrameInputs& inputs,
                                  const Settings& settings, Slot& slot) {
  const auto& fn = device_.fn();
  const detail::ModuleImages& im = images_;
  const VkExtent3D mask = im.godRayMask.extent();
  const detail::GodRaySun sun =
      detail::godRaySun(inputs.view, inputs.projection, inputs.sunDirection);
  // The sun's position in the mask's uv: the mask covers kGodRayDownsample pixels per texel,
  // possibly past the render extent.
  const glm::vec2 pixelsPerMaskUv(float(mask.width * shader::kGodRayDownsample),
                                  float(mask.height * shader::kGodRayDownsample));
  const glm::vec2 renderExtent(float(inputs.renderExtent.width), float(inputs.renderExtent.height));
  const glm::vec2 sunUv = sun.uv * renderExtent / pixelsPerMaskUv;
  godRayParameters_.sun =
      glm::vec4(sunUv, sun.fade, float(sun.fade > 0.0f ? settings.godRaySamples : 0u));
  godRayParameters_.blur =
      glm::vec4(settings.godRayLength, settings.godRayDecay, float(mask.width), float(mask.height));

  beginPass(cmd, detail::Pass::GodRays, "clouds: god rays");
  // Earlier commands of this queue may still read the occlusion image and the mask.
  detail::memoryBarrier(device_, cmd, kHostReadStages | kCompute, kHostReadAccess | kStorageRead,
                        kCompute | VK_PIPELINE_STAGE_2_CLEAR_BIT,
                        kStorageWrite | VK_ACCESS_2_TRANSFER_WRITE_BIT);
  if (sun.fade <= 0.0f) {
    // Nothing on screen says what hides the sun: a clear mask, and nothing for it to do.
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkClearColorValue clear{};
    clear.float32[0] = 1.0f;
    fn.vkCmdClearColorImage(cmd, im.godRayMask.image(), VK_IMAGE_LAYOUT_GENERAL, &clear, 1, &range);
    detail::barrier(device_, cmd, im.godRayMask.image(), VK_IMAGE_LAYOUT_GENERAL,
                    VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, kHostReadStages, kHostReadAccess);
    endPass(cmd, detail::Pass::GodRays);
    return;
  }

  const bool hasDepth = inputs.depthView != VK_NULL_HANDLE;
  detail::SetWriter(device_, slot.godRayOcclusion)
      .storageImage(shader::kGodRayRadiance, im.radiance.view())
      .sampledImage(shader::kGodRayHostDepth,
                    hasDepth ? inputs.depthView : im.depthPlaceholder.view(), nearestSampler_.get(),
                    hasDepth ? inputs.depthLayout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .storageImage(shader::kGodRayOcclusionOut, im.godRayOcclusion.view())
      .commit();
  detail::SetWriter(device_, slot.godRays)
      .sampledImage(shader::kGodRayOcclusion, im.godRayOcclusion.view(),
                    clampedLinearSampler_.get(), VK_IMAGE_LAYOUT_GENERAL)
      .storageImage(shader::kGodRayMaskOut, im.godRayMask.view())
      .commit();

  shader::GodRayOcclusionConstants occlusion{};
  occlusion.renderExtent = glm::uvec2(inputs.renderExtent.width, inputs.renderExtent.height);
  occlusion.maskExtent = glm::uvec2(mask.width, mask.height);
  occlusion.hasDepth = hasDepth ? 1u : 0u;
  occlusion.reversedZ = info_.reversedZ ? 1u : 0u;
  const detail::ComputeProgram& occlusionProgram = programs_[Program::GodRayOcclusion];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, occlusionProgram.find());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, occlusionProgram.layout(), 0, 1,
                             &slot.godRayOcclusion, 0, nullptr);
  fn.vkCmdPushConstants(cmd, occlusionProgram.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                        sizeof(occlusion), &occlusion);
  fn.vkCmdDispatch(cmd, groups(mask.width), groups(mask.height), 1);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kSampledRead);

  const detail::ComputeProgram& blur = programs_[Program::GodRays];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, blur.find());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, blur.layout(), 0, 1,
                             &slot.godRays, 0, nullptr);
  fn.vkCmdPushConstants(cmd, blur.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                        sizeof(godRayParameters_), &godRayParameters_);
  fn.vkCmdDispatch(cmd, groups(mask.width), groups(mask.height), 1);
  detail::barrier(device_, cmd, im.godRayMask.image(), VK_IMAGE_LAYOUT_GENERAL,
                  VK_IMAGE_LAYOUT_GENERAL, kCompute, kStorageWrite, kHostReadStages,
                  kHostReadAccess);
  endPass(cmd, detail::Pass::GodRays);

  // What the composite helper needs of this frame.
  const FrameInputs::AerialPerspective& haze = inputs.aerialPerspective;
  const bool scatters = glm::any(glm::greaterThan(haze.mieScatteringPerMetre, glm::vec3(0.0f)));
  GodRayFrame& frame = godRayFrame_;
  frame.made = true;
  frame.hazed = haze.view != VK_NULL_HANDLE && scatters;
  frame.depthView = inputs.depthView;
  frame.depthLayout = inputs.depthLayout;
  frame.hazeView = haze.view;
  frame.hazeLayout = haze.layout;
  shader::GodRayComposite& u = frame.uniforms;
  u.viewFromClip = glm::inverse(inputs.projection);
  const glm::vec3 sunView = glm::mat3(inputs.view) * glm::normalize(inputs.sunDirection);
  u.sunView = glm::vec4(glm::normalize(sunView), sun.fade);
  u.maskScale =
      glm::vec4(1.0f / pixelsPerMaskUv, info_.reversedZ ? 0.0f : 1.0f, hasDepth ? 1.0f : 0.0f);
  u.rayleighPerMetre = glm::vec4(haze.rayleighScatteringPerMetre, haze.miePhaseG);
  u.miePerMetre = glm::vec4(haze.mieScatteringPerMetre, settings.godRayGlowStrength);
  u.hazeScale = glm::vec4(haze.radianceScale, haze.rangeMetres);
  u.sunIlluminance = glm::vec4(inputs.sunIlluminance, float(haze.slices));
}

std::uint32_t Context::Impl::prepareCompositeGodRays(VkCommandBuffer cmd, Slot& slot) {
  const GodRayFrame& frame = godRayFrame_;
  const detail::ModuleImages& im = images_;
  const VkImageView placeholder = im.depthPlaceholder.view();
  constexpr VkImageLayout kReadOnly = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  const bool depth = frame.made && frame.depthView != VK_NULL_HANDLE;
  const bool haze = frame.made && frame.hazed;
  // Every binding is written (placeholders without god rays): a pipeline may not leave one of
  // its bindings unwritten, even where its variant never reads it.
  detail::SetWriter(device_, slot.composite)
      .sampledImage(shader::kCompositeGodRayMask, frame.made ? im.godRayMask.view() : placeholder,
                    clampedLinearSampler_.get(), frame.made ? VK_IMAGE_LAYOUT_GENERAL : kReadOnly)
      .sampledImage(shader::kCompositeHostDepth, depth ? frame.depthView : placeholder,
                    nearestSampler_.get(), depth ? frame.depthLayout : kReadOnly)
      .sampledImage(shader::kCompositeAerialPerspective,
                    haze ? frame.hazeView : im.hazePlaceholder.view(), clampedLinearSampler_.get(),
                    haze ? frame.hazeLayout : kReadOnly)
      .uniformBuffer(shader::kCompositeGodRays, slot.godRayComposite.buffer(),
                     sizeof(shader::GodRayComposite))
      .commit();
  if (!frame.made) return shader::kGodRaysNone;
  // The slot's previous frame has completed (host contract); earlier commands may still read it.
  detail::memoryBarrier(device_, cmd, kCompute, VK_ACCESS_2_UNIFORM_READ_BIT,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  device_.fn().vkCmdUpdateBuffer(cmd, slot.godRayComposite.buffer(), 0, sizeof(frame.uniforms),
                                 &frame.uniforms);
  detail::memoryBarrier(device_, cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute, VK_ACCESS_2_UNIFORM_READ_BIT);
  return frame.hazed ? shader::kGodRaysMaskHaze : shader::kGodRaysGlow;
}

}  // namespace clouds
