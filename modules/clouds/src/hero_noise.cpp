#include "hero_noise.h"

#include "cloud_types.h"

namespace clouds::detail {

HeroNoise::HeroNoise(const DeviceContext& device)
    : device_(&device),
      image_(device, VK_IMAGE_TYPE_3D, VK_FORMAT_R8G8B8A8_UNORM,
             VkExtent3D{shader::kHeroNoiseSize, shader::kHeroNoiseSize, shader::kHeroNoiseDepth},
             VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
             "hero cloud detail noise mip chain") {}

void HeroNoise::recordGeneration(VkCommandBuffer cmd, const ComputeProgram& generator,
                                 VkDescriptorSet generatorSet, const ComputeProgram& mip,
                                 VkDescriptorSet mipSet, std::uint32_t seed) {
  const auto& fn = device_->fn();
  SetWriter(*device_, generatorSet).storageImage(shader::kGeneratorTarget, image_.view()).commit();
  SetWriter(*device_, mipSet).storageImage(shader::kGeneratorTarget, image_.view()).commit();
  barrier(*device_, cmd, image_.image(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
          VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, kComputeStage, kStorageWrite);
  const auto n = static_cast<std::uint32_t>(shader::kHeroNoiseSize);
  const auto bind = [&](const ComputeProgram& program, VkDescriptorSet set, const void* constants,
                        std::uint32_t bytes) {
    fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.find());
    fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1, &set, 0,
                               nullptr);
    fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, bytes, constants);
  };
  const shader::NoiseConstants noise{seed, n, 0u, 0u};
  bind(generator, generatorSet, &noise, sizeof(noise));
  const std::uint32_t groups = groupsFor(n, shader::kWorkgroupSize3D);
  fn.vkCmdDispatch(cmd, groups, groups, groups);
  for (std::uint32_t level = 1; level < static_cast<std::uint32_t>(shader::kHeroNoiseLevels);
       ++level) {
    memoryBarrier(*device_, cmd, kComputeStage, kStorageWrite, kComputeStage,
                  kStorageRead | kStorageWrite);
    const shader::NoiseMipConstants constants{n, level, 0u, 0u};
    bind(mip, mipSet, &constants, sizeof(constants));
    const std::uint32_t levelGroups = groupsFor(n >> level, shader::kWorkgroupSize3D);
    fn.vkCmdDispatch(cmd, levelGroups, levelGroups, levelGroups);
  }
  memoryBarrier(*device_, cmd, kComputeStage, kStorageWrite, kComputeStage, kStorageRead);
}

}  // namespace clouds::detail
