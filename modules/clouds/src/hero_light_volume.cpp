#include "hero_light_volume.h"

#include "cloud_hero_light.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace clouds::detail {

HeroLightKey heroLightKey(const shader::HeroCloudInstance& instance, const glm::vec3& sunDirection,
                          std::uint32_t detail) {
  return HeroLightKey{instance.extent.w, shader::heroSunIndexDirection(instance, sunDirection),
                      instance.scales.w, instance.scales.y / instance.scales.z, detail};
}

bool heroLightServes(const HeroLightKey& held, const HeroLightKey& wanted) {
  static const float kCosSun = std::cos(glm::radians(kHeroLightSunDegrees));
  return held.assetSlice == wanted.assetSlice && held.detail == wanted.detail &&
         glm::dot(held.sunIndex, wanted.sunIndex) >= kCosSun &&
         std::abs(held.topIndex - wanted.topIndex) <= kHeroLightTopVoxels &&
         std::abs(held.erosionVoxels - wanted.erosionVoxels) <= kHeroLightErosionVoxels;
}

glm::uvec3 heroLightGridSize(const glm::uvec3& assetVoxels) {
  const glm::vec3 texels =
      glm::ceil((glm::vec3(assetVoxels) + 1.0f) / shader::kHeroLightTexelVoxels);
  return glm::uvec3(texels) + 1u;
}

std::uint32_t HeroLightSlots::assign(shader::HeroCloudUniforms& block,
                                     const glm::vec3& sunDirection) {
  ++round_;
  constexpr std::uint32_t kSlots = shader::kMaxHeroClouds;
  std::array<bool, kSlots> taken{};
  std::array<std::optional<std::uint32_t>, kSlots> slotOf{};
  // First, every instance a slot still serves keeps it.
  for (std::uint32_t i = 0; i < block.count.x; ++i) {
    const HeroLightKey wanted = heroLightKey(block.instance[i], sunDirection, block.count.w);
    for (std::uint32_t s = 0; s < kSlots; ++s) {
      if (taken[s] || !held_[s] || !heroLightServes(*held_[s], wanted)) continue;
      taken[s] = true;
      slotOf[i] = s;
      break;
    }
  }
  // Then the others take the free slots, empty ones first, else the least recently used.
  std::uint32_t sweep = 0;
  for (std::uint32_t i = 0; i < block.count.x; ++i) {
    if (slotOf[i]) continue;
    // Empty slots first (0), then the least recently used.
    const auto preference = [&](std::uint32_t slot) -> std::uint64_t {
      return held_[slot] ? lastUsed_[slot] + 1 : 0;
    };
    std::optional<std::uint32_t> best;
    for (std::uint32_t s = 0; s < kSlots; ++s) {
      if (!taken[s] && (!best || preference(s) < preference(*best))) best = s;
    }
    // There are as many slots as instances in a block.
    const std::uint32_t s = *best;
    taken[s] = true;
    slotOf[i] = s;
    held_[s] = heroLightKey(block.instance[i], sunDirection, block.count.w);
    sweep |= 1u << i;
  }
  block.count.y = 0;
  for (std::uint32_t i = 0; i < block.count.x; ++i) {
    lastUsed_[*slotOf[i]] = round_;
    block.count.y |= *slotOf[i] << (shader::kHeroLightSlotBits * i);
  }
  return sweep;
}

namespace {

glm::uvec3 largestGrid(const std::vector<HeroAsset>& assets) {
  glm::uvec3 extent(1u);
  for (const HeroAsset& asset : assets) extent = glm::max(extent, heroLightGridSize(asset.size));
  return extent;
}

}  // namespace

std::uint32_t heroLightSlotExtentCode(const std::vector<HeroAsset>& assets) {
  const glm::uvec3 extent = largestGrid(assets);
  return extent.x | extent.y << 10 | extent.z << 20;
}

HeroLightVolume::HeroLightVolume(const DeviceContext& device, const std::vector<HeroAsset>& assets)
    : device_(&device),
      slotExtent_(largestGrid(assets)),
      slotExtentCode_(heroLightSlotExtentCode(assets)),
      image_(device, VK_IMAGE_TYPE_3D, VK_FORMAT_R16_SFLOAT,
             VkExtent3D{2 * slotExtent_.x, 2 * slotExtent_.y, 2 * slotExtent_.z},
             VK_IMAGE_USAGE_STORAGE_BIT, "hero cloud light volume") {
  static_assert(shader::kMaxHeroClouds <= 8, "the slots lie in a 2 x 2 x 2 grid");
}

std::uint32_t HeroLightVolume::assignSlots(shader::HeroCloudUniforms& block,
                                           const glm::vec3& sunDirection) {
  block.count.z = slotExtentCode_;
  return slots_.assign(block, sunDirection);
}

void HeroLightVolume::recordFirstUse(VkCommandBuffer cmd) {
  if (ready_) return;
  barrier(*device_, cmd, image_.image(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
          VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, kComputeStage, kStorageRead | kStorageWrite);
  ready_ = true;
}

void HeroLightVolume::recordSweep(VkCommandBuffer cmd, const ComputeProgram& program,
                                  VkDescriptorSet set, VkImageView heroAtlas, VkImageView heroNoise,
                                  VkBuffer heroBlock, std::uint32_t instances,
                                  const glm::vec3& sunDirection) {
  const auto& fn = device_->fn();
  SetWriter(*device_, set)
      .storageImage(shader::kLightSweepAtlas, heroAtlas)
      .uniformBuffer(shader::kLightSweepClouds, heroBlock, sizeof(shader::HeroCloudUniforms))
      .storageImage(shader::kLightSweepVolume, image_.view())
      .storageImage(shader::kLightSweepNoise, heroNoise)
      .commit();
  // Earlier frames' marches may still read the slots this sweep rewrites.
  memoryBarrier(*device_, cmd, kComputeStage, kStorageRead, kComputeStage,
                kStorageRead | kStorageWrite);
  shader::HeroLightConstants constants{};
  constants.sunDirection = glm::vec4(sunDirection, 0.0f);
  constants.instances = instances;
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.find());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1, &set, 0,
                             nullptr);
  fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                        &constants);
  fn.vkCmdDispatch(cmd, static_cast<std::uint32_t>(std::popcount(instances)), 1, 1);
  memoryBarrier(*device_, cmd, kComputeStage, kStorageWrite, kComputeStage, kStorageRead);
}

}  // namespace clouds::detail
