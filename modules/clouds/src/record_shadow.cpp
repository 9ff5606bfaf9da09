// Recording the cloud shadow map: this frame's field uniforms into the slot's shadow buffer,
// then one dispatch per cascade due (shadow_cascades.h decides which) or for the slice of rows
// due of a cascade made over several frames (into the spare cascade, copied into the atlas
// after its last), then, with the host's terrain, one more per cascade completed whose rays
// moved for its terrain channel, ending with the atlas visible to the host's compute and
// fragment shaders.
#include <algorithm>

#include "context_impl.h"
#include "pipeline_variants.h"

namespace clouds {

using detail::Program;

namespace {

constexpr VkPipelineStageFlags2 kCompute = detail::kComputeStage;
using detail::kHostReadAccess;
using detail::kHostReadStages;

}  // namespace

void Context::Impl::recordShadowMap(VkCommandBuffer cmd, const FrameInputs& inputs,
                                    const Settings& settings, const detail::ShadowPlan& plan,
                                    Slot& slot) {
  const auto& fn = device_.fn();
  const detail::ModuleImages& im = images_;
  beginPass(cmd, detail::Pass::ShadowMap, "clouds: shadow map");

  // The field as this frame's march sees it (camera-relative offsets, coverage, extinction);
  // the view and temporal fields are not read. A slice after a cascade's first uses the
  // first's, so that all its slices see the same clouds from the same camera.
  if (!plan.slice || plan.slice->first) {
    sliceUniforms_ =
        detail::buildUniforms(inputs, settings, detail::UniformContext{info_.reversedZ});
    sliceUniforms_.flags |= debugFlags_;
    sliceHeroClouds_ = heroBlock(inputs, settings);
  }
  const bool heroes = sliceHeroClouds_.count.x > 0;
  const shader::CloudUniforms& uniforms = sliceUniforms_;
  lastShadowUniforms_ = uniforms;
  lastShadowJobs_.clear();
  // The slot's previous frame has completed (host contract); earlier commands of this queue may
  // still read the buffer, and the host's passes the map; the slices before this one wrote the
  // spare cascade.
  detail::memoryBarrier(
      device_, cmd, kHostReadStages | kCompute,
      VK_ACCESS_2_UNIFORM_READ_BIT | kHostReadAccess | detail::kStorageWrite,
      VK_PIPELINE_STAGE_2_TRANSFER_BIT | kCompute,
      VK_ACCESS_2_TRANSFER_WRITE_BIT | detail::kStorageRead | detail::kStorageWrite);
  fn.vkCmdUpdateBuffer(cmd, slot.shadowUniforms.buffer(), 0, sizeof(uniforms), &uniforms);
  if (heroes) {
    fn.vkCmdUpdateBuffer(cmd, slot.shadowHeroClouds.buffer(), 0, sizeof(sliceHeroClouds_),
                         &sliceHeroClouds_);
  }
  detail::memoryBarrier(device_, cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute, VK_ACCESS_2_UNIFORM_READ_BIT);

  using namespace shader;
  // Without a spare cascade (one frame per cascade) the atlas stands in for it: never written.
  const VkImageView spare = im.shadowSpare ? im.shadowSpare.view() : im.shadowMap.view();
  detail::SetWriter(device_, slot.shadowMap)
      .uniformBuffer(kBindingUniforms, slot.shadowUniforms.buffer(), sizeof(CloudUniforms))
      .storageImage(kShadowShapeNoise, im.shapeNoise.view())
      .storageImage(kShadowWeatherMap, weatherMap().view())
      .storageImage(kShadowWeatherMaxFine, im.weatherMaxFine.view())
      .storageImage(kShadowWeatherMaxCoarse, im.weatherMaxCoarse.view())
      .storageImage(kShadowMapOut, im.shadowMap.view())
      .storageImage(kShadowMapSpare, spare)
      // Without hero clouds, stand-ins the variant never reads.
      .storageImage(kShadowHeroAtlas, heroes ? heroAtlas_->image().view() : im.shapeNoise.view())
      .uniformBuffer(kShadowHeroClouds,
                     heroes ? slot.shadowHeroClouds.buffer() : slot.shadowUniforms.buffer(),
                     sizeof(HeroCloudUniforms))
      .storageImage(kShadowHeroNoise, heroNoiseView())
      .commit();

  const detail::ComputeProgram& program = programs_[Program::ShadowMap];
  fn.vkCmdBindPipeline(
      cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
      program.find(detail::shadowMapKey(
          settings, heroes ? detail::heroCloudVariant(sliceHeroClouds_) : shader::kHeroCloudsOff)));
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1,
                             &slot.shadowMap, 0, nullptr);
  const auto dispatch = [&](const ShadowMapConstants& constants) {
    fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                          &constants);
    lastShadowJobs_.push_back(constants);
    fn.vkCmdDispatch(cmd, detail::groupsFor(constants.resolution, kWorkgroupSize2D),
                     detail::groupsFor(constants.rowCount, kWorkgroupSize2D), 1);
  };
  // The cascades made into the atlas this frame, whole: their terrain channel is due unless
  // they kept it.
  std::vector<detail::CascadeJob> completed = plan.jobs;
  for (const detail::CascadeJob& job : plan.jobs) {
    dispatch(detail::shadowMapConstants(job, inputs.cameraPosition, settings));
  }
  if (plan.slice) {
    const detail::CascadeSlice& slice = *plan.slice;
    ShadowMapConstants constants =
        detail::shadowMapConstants(slice.job, slice.cameraPosition, settings);
    constants.flags |= kShadowTexelToSpare;
    constants.firstRow = slice.firstRow;
    constants.rowCount = slice.rowCount;
    dispatch(constants);
    if (slice.last) {
      copySpareIntoAtlas(cmd, slice.job.cascade, settings.shadowMapResolution);
      completed.push_back(slice.job);
    }
  }
  const bool terrainDue =
      inputs.terrain.heightView != VK_NULL_HANDLE &&
      std::any_of(completed.begin(), completed.end(),
                  [](const detail::CascadeJob& job) { return !job.keepTerrain; });
  if (terrainDue) {
    // The terrain pass reads the clouds' channels back and writes them with its own.
    detail::memoryBarrier(device_, cmd, kCompute, detail::kStorageWrite, kCompute,
                          detail::kStorageRead | detail::kStorageWrite);
    endPass(cmd, detail::Pass::ShadowMap);
    recordTerrainShadow(cmd, inputs, settings, completed, slot);
    return;
  }
  makeShadowMapVisible(cmd);
  endPass(cmd, detail::Pass::ShadowMap);
}

// The cascade made in slices goes into its square of the atlas in one copy, so receivers go
// from the old cascade to the new one between two frames. A transfer, not a dispatch: on
// lavapipe a dispatch's invocations that return at once cost nearly as much as marching ones.
void Context::Impl::copySpareIntoAtlas(VkCommandBuffer cmd, std::uint32_t cascade,
                                       std::uint32_t resolution) {
  const auto& fn = device_.fn();
  constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
  const VkImage spare = images_.shadowSpare.image();
  const VkImage atlas = images_.shadowMap.image();
  detail::barrier(device_, cmd, spare, VK_IMAGE_LAYOUT_GENERAL,
                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kCompute, detail::kStorageWrite, kTransfer,
                  VK_ACCESS_2_TRANSFER_READ_BIT);
  // The atlas was last read by the host's passes and written by this pass's dispatches.
  detail::barrier(device_, cmd, atlas, VK_IMAGE_LAYOUT_GENERAL,
                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kCompute | kHostReadStages,
                  detail::kStorageWrite | kHostReadAccess, kTransfer,
                  VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkImageCopy region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstSubresource = region.srcSubresource;
  region.dstOffset = {static_cast<std::int32_t>(cascade * resolution), 0, 0};
  region.extent = {resolution, resolution, 1};
  fn.vkCmdCopyImage(cmd, spare, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, atlas,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  detail::barrier(device_, cmd, spare, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  VK_IMAGE_LAYOUT_GENERAL, kTransfer, VK_ACCESS_2_NONE, kCompute,
                  detail::kStorageWrite);
  detail::barrier(device_, cmd, atlas, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_IMAGE_LAYOUT_GENERAL, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute,
                  detail::kStorageRead | detail::kStorageWrite);
}

// The barrier belongs to the pass that ends with it: on lavapipe a dispatch only starts the
// work, and the barrier waits for it.
void Context::Impl::makeShadowMapVisible(VkCommandBuffer cmd) {
  detail::barrier(device_, cmd, images_.shadowMap.image(), VK_IMAGE_LAYOUT_GENERAL,
                  VK_IMAGE_LAYOUT_GENERAL, kCompute, detail::kStorageWrite, kHostReadStages,
                  kHostReadAccess);
}

void Context::Impl::recordTerrainShadow(VkCommandBuffer cmd, const FrameInputs& inputs,
                                        const Settings& settings,
                                        const std::vector<detail::CascadeJob>& jobs, Slot& slot) {
  const auto& fn = device_.fn();
  beginPass(cmd, detail::Pass::TerrainShadow, "clouds: terrain shadow");
  detail::SetWriter(device_, slot.terrainShadow)
      .sampledImage(shader::kTerrainShadowHeight, inputs.terrain.heightView,
                    clampedLinearSampler_.get(), inputs.terrain.heightLayout)
      .storageImage(shader::kTerrainShadowMap, images_.shadowMap.view())
      .commit();
  const detail::ComputeProgram& program = programs_[Program::TerrainShadow];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.find());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1,
                             &slot.terrainShadow, 0, nullptr);
  const std::uint32_t groups =
      detail::groupsFor(settings.shadowMapResolution, shader::kWorkgroupSize2D);
  lastTerrainShadowJobs_.clear();
  for (const detail::CascadeJob& job : jobs) {
    if (job.keepTerrain) continue;  // made over the same rays: still right
    const shader::TerrainShadowConstants constants =
        detail::terrainShadowConstants(job, inputs, settings);
    fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                          &constants);
    lastTerrainShadowJobs_.push_back(constants);
    fn.vkCmdDispatch(cmd, groups, groups, 1);
  }
  makeShadowMapVisible(cmd);
  endPass(cmd, detail::Pass::TerrainShadow);
}

}  // namespace clouds
