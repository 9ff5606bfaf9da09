#pragma once
// Hero clouds' light volume (Settings::heroLight Volume; cloud_hero_light.h): an R16F 3D image
// of kMaxHeroClouds slots, each the light grid of one of this frame's instances, and the
// bookkeeping that sweeps a slot only when what it holds no longer serves its instance (the
// sun turned, or the cloud's asset or life changed), so a still scene sweeps once.
//
// A slot's extent is the largest asset's light grid; the slots lie in a 2 x 2 x 2 grid. The
// instances tell the shaders their slots in the hero block's header (count.y, count.z).
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "cloud_types.h"
#include "hero_clouds.h"
#include "kit.h"

namespace clouds::detail {

// What a slot was swept for: what the sweep reads besides the atlas (the instance's size,
// density and fade scale the lookup, and the extinction the march).
struct HeroLightKey {
  float assetSlice = 0.0f;     // the asset: its origin in the atlas (HeroCloudInstance::extent.w)
  glm::vec3 sunIndex{0.0f};    // the sun in its index space, unit
  float topIndex = 0.0f;       // its life: the top (index y)
  float erosionVoxels = 0.0f;  // and the erosion (voxels)
  std::uint32_t detail = 0;    // the block's detail (count.w): the density the sweep integrates
};

// How far the sun may turn, and the life move, before an instance's slot is swept again: half a
// degree moves a shadow 9 m over a kilometre of cloud, under a voxel of the shipped clouds; a
// quarter voxel of a growing top steps the light towards the sun by 0.0035 on average at the
// sweep (a whole voxel: 0.012, a flicker at the top; HeroLightVolume.AGrowingClouds...).
inline constexpr float kHeroLightSunDegrees = 0.5f;
inline constexpr float kHeroLightTopVoxels = 0.25f;
inline constexpr float kHeroLightErosionVoxels = 0.1f;

// `detail`: the block's (HeroCloudUniforms::count.w).
HeroLightKey heroLightKey(const shader::HeroCloudInstance& instance, const glm::vec3& sunDirection,
                          std::uint32_t detail);
// Whether a slot swept for `held` serves an instance that wants `wanted`.
bool heroLightServes(const HeroLightKey& held, const HeroLightKey& wanted);
// An asset's light grid (cloud_hero_light.h's heroLightSize()).
glm::uvec3 heroLightGridSize(const glm::uvec3& assetVoxels);
// The slots' extent for `assets` (their largest light grid), as the hero block's header holds it
// (HeroCloudUniforms::count.z).
std::uint32_t heroLightSlotExtentCode(const std::vector<HeroAsset>& assets);

// The slots' bookkeeping, apart from the image (tested alone).
class HeroLightSlots {
 public:
  // Gives each of `block`'s instances a slot (block.count.y): the one that serves it, else the
  // least recently used. Returns the instances (bit i: instance i) whose slots must be swept
  // this frame.
  std::uint32_t assign(shader::HeroCloudUniforms& block, const glm::vec3& sunDirection);

 private:
  std::array<std::optional<HeroLightKey>, shader::kMaxHeroClouds> held_{};
  std::array<std::uint64_t, shader::kMaxHeroClouds> lastUsed_{};
  std::uint64_t round_ = 0;
};

class HeroLightVolume {
 public:
  HeroLightVolume(const DeviceContext& device, const std::vector<HeroAsset>& assets);

  // Slots for `block`'s instances (its count.y and z); returns the instances to sweep.
  std::uint32_t assignSlots(shader::HeroCloudUniforms& block, const glm::vec3& sunDirection);
  // Records the sweep of `instances` (assignSlots()'s, not 0) of the block in `heroBlock` over
  // `heroAtlas` and `heroNoise` (the detail noise, or a stand-in when the block's header says
  // none) with `program` (hero_light_volume.comp) and its descriptor set `set`; the march that
  // follows reads the result.
  void recordSweep(VkCommandBuffer cmd, const ComputeProgram& program, VkDescriptorSet set,
                   VkImageView heroAtlas, VkImageView heroNoise, VkBuffer heroBlock,
                   std::uint32_t instances, const glm::vec3& sunDirection);
  // Readies the image for the march's reads on its first frame (a frame that sweeps nothing
  // still binds it).
  void recordFirstUse(VkCommandBuffer cmd);

  const OwnedImage& image() const { return image_; }
  VkDeviceSize bytes() const { return image_.bytes(); }

 private:
  const DeviceContext* device_;
  glm::uvec3 slotExtent_{0u};
  std::uint32_t slotExtentCode_ = 0;
  OwnedImage image_;
  HeroLightSlots slots_;
  bool ready_ = false;  // in GENERAL layout
};

}  // namespace clouds::detail
