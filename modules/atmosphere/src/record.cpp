// Recording the atmosphere's frame (dispatch) and its pass over the host's colour (render).
// Every image stays in GENERAL: written as storage, sampled by later passes and by hosts.
#include <algorithm>
#include <cmath>

#include "context_impl.h"
#include "uniforms.h"

namespace atmosphere {

using detail::Program;

namespace {

constexpr VkPipelineStageFlags2 kCompute = detail::kComputeStage;
constexpr VkAccessFlags2 kSampled = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
// Where hosts may read the outputs.
constexpr VkPipelineStageFlags2 kReadStages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                                              VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                                              VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;

}  // namespace

void Context::Impl::beginPass(VkCommandBuffer cmd, Program program) {
  device_.beginLabel(cmd, detail::kPassNames[detail::index(program)]);
  if (timer_) timer_->begin(cmd, detail::index(program));
}

void Context::Impl::endPass(VkCommandBuffer cmd, Program program) {
  if (timer_) timer_->end(cmd, detail::index(program));
  device_.endLabel(cmd);
}

// The index of the uniform block's element the compute passes read, always 0
// (atmosphere_uniforms.glsl says why it is a push constant).
void Context::Impl::pushUniformsIndex(VkCommandBuffer cmd, VkPipelineLayout layout) {
  const std::uint32_t index = 0;
  device_.fn().vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(index),
                                  &index);
}

void Context::Impl::bindAndDispatch(VkCommandBuffer cmd, Program program, const Slot& slot,
                                    std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  const auto& fn = device_.fn();
  const detail::ComputeProgram& p = programs_[program];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.find());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout(), 0, 1,
                             &slot.sets[detail::index(program)], 0, nullptr);
  pushUniformsIndex(cmd, p.layout());
  fn.vkCmdDispatch(cmd, x, y, z);
}

void Context::Impl::dispatch(const FrameInputs& inputs, const Parameters& parameters,
                             const Settings& settings) {
  const auto& fn = device_.fn();
  const VkCommandBuffer cmd = inputs.commandBuffer;
  releaseRetired(inputs.frameIndex);
  const auto slotIndex = static_cast<std::uint32_t>(inputs.frameIndex % slots_.size());
  Slot& slot = slots_[slotIndex];
  device_.beginLabel(cmd, "atmosphere");
  if (timer_) timer_->beginFrame(cmd, slotIndex);
  for (VkImage image : pendingLayouts_) {
    detail::barrier(device_, cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, kCompute,
                    kSampled | detail::kStorageWrite);
  }
  pendingLayouts_.clear();

  lastUniforms_ = detail::buildUniforms(inputs, parameters, settings, info_.reversedZ);
  // Earlier commands may still read this slot's uniforms and the images written below.
  detail::memoryBarrier(device_, cmd, kReadStages, VK_ACCESS_2_UNIFORM_READ_BIT | kSampled,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT | kCompute,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT | detail::kStorageWrite);
  fn.vkCmdUpdateBuffer(cmd, slot.uniforms.buffer(), 0, sizeof(lastUniforms_), &lastUniforms_);
  if (inputs.cloudShadow.view != VK_NULL_HANDLE) {  // read only with a map
    fn.vkCmdUpdateBuffer(cmd, slot.cloudShadow.buffer(), 0, sizeof(inputs.cloudShadow.parameters),
                         inputs.cloudShadow.parameters);
  }
  detail::memoryBarrier(device_, cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, kReadStages, VK_ACCESS_2_UNIFORM_READ_BIT);
  writeSets(slot, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED, VK_NULL_HANDLE, &inputs.cloudShadow);

  // A pass over a width x height texture whose result the next passes sample.
  const auto lutPass = [&](Program program, std::uint32_t width, std::uint32_t height) {
    const std::uint32_t group = shader::kWorkgroupSize2D;
    beginPass(cmd, program);
    bindAndDispatch(cmd, program, slot, detail::groupsFor(width, group),
                    detail::groupsFor(height, group));
    detail::memoryBarrier(device_, cmd, kCompute, detail::kStorageWrite, kCompute, kSampled);
    endPass(cmd, program);
  };
  if (lutsDirty_) {
    // Depend only on the parameters: recorded when they (or their recipe) changed.
    lutPass(Program::Transmittance, settings.transmittanceWidth, settings.transmittanceHeight);
    lutPass(Program::MultiScattering, settings.multiScatteringSize, settings.multiScatteringSize);
    lutsDirty_ = false;
    ++lutBuilds_;
  }
  const double altitude = std::max(inputs.cameraPosition.y, 1.0);  // as the uniforms clamp it
  if (!skyViewServes(altitude, settings)) {
    lutPass(Program::SkyView, settings.skyViewWidth, settings.skyViewHeight);
    skyViewBuild_ = SkyViewBuild{altitude, lastUniforms_.sunDirection.y};
    ++skyViewBuilds_;
  }
  lutPass(Program::AerialPerspective, settings.aerialPerspectiveWidth,
          settings.aerialPerspectiveHeight);
  beginPass(cmd, Program::Environment);
  bindAndDispatch(cmd, Program::Environment, slot, 1, 1);
  // The outputs, to hosts' compute and fragment shaders; the measurement, to the host.
  detail::memoryBarrier(device_, cmd, kCompute, detail::kStorageWrite, kReadStages, kSampled);
  detail::memoryBarrier(device_, cmd, kCompute, detail::kStorageWrite, VK_PIPELINE_STAGE_2_HOST_BIT,
                        VK_ACCESS_2_HOST_READ_BIT);
  endPass(cmd, Program::Environment);
  device_.endLabel(cmd);

  slot.lightingFrame = inputs.frameIndex;
  lastSlot_ = slotIndex;
  lastFrameIndex_ = inputs.frameIndex;
  lastExtent_ = inputs.renderExtent;
}

// The sky-view LUT depends on the camera's altitude and the sun's elevation only (its azimuths
// are measured from the sun's, the model's camera stands at the planet's pole), so it is kept
// while the sun has not moved and the altitude is within Settings::skyViewAltitudeTolerance of
// the one it was built at: 0.85 of the atmosphere's 2.5 ms a frame at Medium on lavapipe, in a
// flight that mostly keeps its height. (Its readers use this frame's horizon dip; the kept
// LUT's differs by at most half the tolerance of it.)
bool Context::Impl::skyViewServes(double altitudeMetres, const Settings& settings) const {
  if (!skyViewBuild_) return false;
  const SkyViewBuild& built = *skyViewBuild_;
  return built.sunHeight == lastUniforms_.sunDirection.y &&
         std::abs(altitudeMetres - built.altitudeMetres) <=
             double(settings.skyViewAltitudeTolerance) * built.altitudeMetres;
}

void Context::Impl::writeSets(Slot& slot, VkImageView depth, VkImageLayout depthLayout,
                              VkImageView color, const FrameInputs::CloudShadow* shadow) {
  using namespace shader;
  const VkSampler linear = linearSampler_.get();
  const VkImageLayout general = VK_IMAGE_LAYOUT_GENERAL;
  const VkBuffer uniforms = slot.uniforms.buffer();
  const VkDeviceSize bytes = sizeof(AtmosphereUniforms);
  const auto set = [&](Program p) { return slot.sets[detail::index(p)]; };
  if (color != VK_NULL_HANDLE) {
    // render(): the host's colour and depth change from call to call.
    const bool hasDepth = depth != VK_NULL_HANDLE;
    detail::SetWriter(device_, set(Program::Apply))
        .uniformBuffer(kBindingUniforms, uniforms, bytes)
        .sampledImage(kBindingSkyView, skyView_.view(), linear, general)
        .sampledImage(kBindingAerialPerspective, aerialPerspective_.view(), linear, general)
        .sampledImage(kBindingHostDepth, hasDepth ? depth : depthPlaceholder_.view(),
                      nearestSampler_.get(), hasDepth ? depthLayout : general)
        .storageImage(kBindingTarget, color)
        .commit();
    return;
  }
  detail::SetWriter(device_, set(Program::Transmittance))
      .uniformBuffer(kBindingUniforms, uniforms, bytes)
      .storageImage(kBindingTarget, transmittance_.view())
      .commit();
  detail::SetWriter(device_, set(Program::MultiScattering))
      .uniformBuffer(kBindingUniforms, uniforms, bytes)
      .sampledImage(kBindingTransmittance, transmittance_.view(), linear, general)
      .storageImage(kBindingTarget, multiScattering_.view())
      .commit();
  detail::SetWriter(device_, set(Program::SkyView))
      .uniformBuffer(kBindingUniforms, uniforms, bytes)
      .sampledImage(kBindingTransmittance, transmittance_.view(), linear, general)
      .sampledImage(kBindingMultiScattering, multiScattering_.view(), linear, general)
      .storageImage(kBindingTarget, skyView_.view())
      .commit();
  // Without a cloud shadow map any 2D image fills its binding (the shader does not read it).
  const bool shadowed = shadow != nullptr && shadow->view != VK_NULL_HANDLE;
  detail::SetWriter(device_, set(Program::AerialPerspective))
      .uniformBuffer(kBindingUniforms, uniforms, bytes)
      .sampledImage(kBindingTransmittance, transmittance_.view(), linear, general)
      .sampledImage(kBindingMultiScattering, multiScattering_.view(), linear, general)
      .storageImage(kBindingTarget, aerialPerspective_.view())
      .sampledImage(kBindingCloudShadow, shadowed ? shadow->view : depthPlaceholder_.view(), linear,
                    shadowed ? shadow->layout : general)
      .uniformBuffer(kBindingCloudShadowParameters, slot.cloudShadow.buffer(),
                     sizeof(FrameInputs::CloudShadow::parameters))
      .commit();
  if (skyDraw_) {
    detail::SetWriter(device_, slot.skyDrawSet)
        .uniformBuffer(kBindingUniforms, uniforms, bytes)
        .sampledImage(kBindingSkyView, skyView_.view(), linear, general)
        .commit();
  }
  detail::SetWriter(device_, set(Program::Environment))
      .uniformBuffer(kBindingUniforms, uniforms, bytes)
      .sampledImage(kBindingTransmittance, transmittance_.view(), linear, general)
      .sampledImage(kBindingSkyView, skyView_.view(), linear, general)
      .storageImage(kBindingTarget, environment_.view())
      .storageBuffer(kBindingSkyLighting, slot.lighting.buffer(), sizeof(shader::SkyLighting))
      .commit();
}

void Context::Impl::render(VkCommandBuffer cmd, VkImageView color, VkImageView depth,
                           VkImageLayout depthLayout) {
  Slot& slot = slots_[lastSlot_];
  writeSets(slot, depth, depthLayout, color);
  beginPass(cmd, Program::Apply);
  const detail::ComputeProgram& p = programs_[Program::Apply];
  const auto& fn = device_.fn();
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                       p.find(detail::applyKey(depth != VK_NULL_HANDLE, info_.reversedZ)));
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout(), 0, 1,
                             &slot.sets[detail::index(Program::Apply)], 0, nullptr);
  pushUniformsIndex(cmd, p.layout());
  const std::uint32_t group = shader::kWorkgroupSize2D;
  fn.vkCmdDispatch(cmd, detail::groupsFor(lastExtent_.width, group),
                   detail::groupsFor(lastExtent_.height, group), 1);
  endPass(cmd, Program::Apply);
}

void Context::Impl::drawSky(VkCommandBuffer cmd) {
  const Slot& slot = slots_[lastSlot_];
  const auto& fn = device_.fn();
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, skyDraw_->pipeline());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, skyDraw_->layout(), 0, 1,
                             &slot.skyDrawSet, 0, nullptr);
  const VkViewport viewport{0.0f, 0.0f, float(lastExtent_.width), float(lastExtent_.height),
                            0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, lastExtent_};
  fn.vkCmdSetViewport(cmd, 0, 1, &viewport);
  fn.vkCmdSetScissor(cmd, 0, 1, &scissor);
  fn.vkCmdDraw(cmd, 3, 1, 0, 0);
}

}  // namespace atmosphere
