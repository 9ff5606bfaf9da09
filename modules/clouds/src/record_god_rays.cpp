// Recording the god-ray mask (fxcontracts/god_rays.h) between the reconstruction and the upsample:
// the occlusion image (the reconstructed clouds' transmittance where the scene distance is the
// sky, the near field's laid over it when the frame has one), then its radial blur towards the sun
// with the light the upsample adds to the sky's pixels (a quarter of the resolution holds it: it is
// smooth but for the mask). With the sun far off screen, behind the camera or set, or nothing
// marched, only a clear of the mask to 1.
#include "context_impl.h"
#include "god_rays.h"
#include "kit.h"
#include "pipeline_variants.h"

namespace clouds {
namespace {

using detail::kStorageRead;
using detail::kStorageWrite;
using detail::Program;
constexpr VkPipelineStageFlags2 kCompute = detail::kComputeStage;
using detail::kHostReadAccess;
using detail::kHostReadStages;
constexpr VkAccessFlags2 kSampledRead = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_TRANSFER_BIT;

std::uint32_t groups(std::uint32_t n) {
  return detail::groupsFor(n, shader::kWorkgroupSize2D);
}

}  // namespace

bool Context::Impl::recordGodRays(VkCommandBuffer cmd, const FrameInputs& inputs,
                                  const Settings& settings, const detail::OwnedImage& traceSamples,
                                  VkImageView nearField, bool traced, Slot& slot) {
  const auto& fn = device_.fn();
  const detail::ModuleImages& im = images_;
  const VkExtent3D mask = im.godRayMask.extent();
  detail::GodRaySun sun = detail::godRaySun(inputs.view, inputs.projection, inputs.sunDirection);
  if (!traced) sun.fade = 0.0f;
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
  // Earlier commands of this queue may still read the god-ray images and uniforms.
  detail::memoryBarrier(device_, cmd, kHostReadStages | kCompute,
                        kHostReadAccess | kStorageRead | VK_ACCESS_2_UNIFORM_READ_BIT,
                        kCompute | VK_PIPELINE_STAGE_2_CLEAR_BIT | kTransfer,
                        kStorageWrite | VK_ACCESS_2_TRANSFER_WRITE_BIT);
  if (sun.fade <= 0.0f) {
    // Nothing on screen says what hides the sun: a clear mask, and no light to add.
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkClearColorValue clear{};
    clear.float32[0] = 1.0f;
    fn.vkCmdClearColorImage(cmd, im.godRayMask.image(), VK_IMAGE_LAYOUT_GENERAL, &clear, 1, &range);
    detail::barrier(device_, cmd, im.godRayMask.image(), VK_IMAGE_LAYOUT_GENERAL,
                    VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, kHostReadStages, kHostReadAccess);
    endPass(cmd, detail::Pass::GodRays);
    return false;
  }

  const FrameInputs::AerialPerspective& haze = inputs.aerialPerspective;
  const bool scatters = glm::any(glm::greaterThan(haze.mieScatteringPerMetre, glm::vec3(0.0f)));
  const bool hazed = haze.view != VK_NULL_HANDLE && scatters;
  shader::GodRayLightUniforms u{};
  u.viewFromClip = glm::inverse(inputs.projection);
  const glm::vec3 sunView = glm::mat3(inputs.view) * glm::normalize(inputs.sunDirection);
  u.sunView = glm::vec4(glm::normalize(sunView), sun.fade);
  u.screenScale = glm::vec4(renderExtent / pixelsPerMaskUv, info_.reversedZ ? 1.0f : 0.0f, 0.0f);
  u.rayleighPerMetre = glm::vec4(haze.rayleighScatteringPerMetre, haze.miePhaseG);
  u.miePerMetre = glm::vec4(haze.mieScatteringPerMetre, settings.godRayGlowStrength);
  u.hazeScale = glm::vec4(haze.radianceScale, haze.rangeMetres);
  u.sunIlluminance = glm::vec4(inputs.sunIlluminance, float(haze.slices));
  fn.vkCmdUpdateBuffer(cmd, slot.godRayLight.buffer(), 0, sizeof(u), &u);
  detail::memoryBarrier(device_, cmd, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute,
                        VK_ACCESS_2_UNIFORM_READ_BIT);

  detail::SetWriter(device_, slot.godRayOcclusion)
      .uniformBuffer(shader::kBindingUniforms, slot.uniforms.buffer(),
                     sizeof(shader::CloudUniforms))
      .storageImage(shader::kGodRayTraceSamples, traceSamples.view())
      .storageImage(shader::kGodRaySceneDistance, im.sceneDistance.view())
      .storageImage(shader::kGodRayOcclusionOut, im.godRayOcclusion.view())
      // Without a near field the variant reads none: the trace image stands in for it.
      .storageImage(shader::kGodRayNearField,
                    nearField != VK_NULL_HANDLE ? nearField : traceSamples.view())
      .commit();
  detail::SetWriter(device_, slot.godRays)
      .sampledImage(shader::kGodRayOcclusion, im.godRayOcclusion.view(),
                    clampedLinearSampler_.get(), VK_IMAGE_LAYOUT_GENERAL)
      .storageImage(shader::kGodRayMaskOut, im.godRayMask.view())
      .sampledImage(shader::kGodRayHaze, hazed ? haze.view : im.hazePlaceholder.view(),
                    clampedLinearSampler_.get(),
                    hazed ? haze.layout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
      .uniformBuffer(shader::kGodRayUniforms, slot.godRayLight.buffer(),
                     sizeof(shader::GodRayLightUniforms))
      .storageImage(shader::kGodRayLightOut, im.godRayLight.view())
      .commit();

  shader::GodRayOcclusionConstants occlusion{};
  occlusion.maskExtent = glm::uvec2(mask.width, mask.height);
  const detail::ComputeProgram& occlusionProgram = programs_[Program::GodRayOcclusion];
  fn.vkCmdBindPipeline(
      cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
      occlusionProgram.find(detail::godRayOcclusionKey(nearField != VK_NULL_HANDLE)));
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, occlusionProgram.layout(), 0, 1,
                             &slot.godRayOcclusion, 0, nullptr);
  fn.vkCmdPushConstants(cmd, occlusionProgram.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                        sizeof(occlusion), &occlusion);
  fn.vkCmdDispatch(cmd, groups(mask.width), groups(mask.height), 1);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kSampledRead);

  const detail::ComputeProgram& blur = programs_[Program::GodRays];
  fn.vkCmdBindPipeline(
      cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
      blur.find(detail::godRaysKey(hazed ? shader::kGodRaysMaskHaze : shader::kGodRaysGlow)));
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, blur.layout(), 0, 1,
                             &slot.godRays, 0, nullptr);
  fn.vkCmdPushConstants(cmd, blur.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                        sizeof(godRayParameters_), &godRayParameters_);
  fn.vkCmdDispatch(cmd, groups(mask.width), groups(mask.height), 1);
  for (const detail::OwnedImage* image : {&im.godRayMask, &im.godRayLight}) {
    detail::barrier(device_, cmd, image->image(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                    kCompute, kStorageWrite, kHostReadStages, kHostReadAccess);
  }
  endPass(cmd, detail::Pass::GodRays);
  return true;
}

}  // namespace clouds
