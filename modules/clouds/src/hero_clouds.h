#pragma once
// Hero clouds on the GPU: the assets a host gave (Context::setHeroCloudAssets) packed into one
// RGBA8 3D atlas, uploaded by the next frame's commands, and each frame's instances as the
// march's uniform block (shader::HeroCloudUniforms, cloud_hero.h).
//
// The assets lie one after the other along z (the atlas as wide and high as the widest and
// highest asset) or along x (as high and deep as the highest and deepest), whichever takes fewer
// texels. Its texels: R profile, G detail type, B density scale (the NVDF's unorm8
// fields as they are) and A the signed distance at 8 bits, rounded down from the file's 16 so
// that it stays a bound the march may jump by.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cloud_types.h"
#include "clouds/clouds.h"
#include "clouds/nvdf.h"
#include "kit.h"

namespace clouds::detail {

struct HeroAsset {
  glm::uvec3 size{0u};
  glm::uvec3 atlasOrigin{0u};  // its first texel in the atlas (y is 0)
  float voxelMetres = 0.0f;
  glm::vec3 originMetres{0.0f};
  float densityMultiplier = 1.0f;
};

struct HeroAtlasLayout {
  VkExtent3D extent{0, 0, 0};
  std::vector<HeroAsset> assets;
  std::vector<std::uint8_t> texels;  // RGBA8, x fastest, then y, then z
};

// The A channel's code of a signed distance (m) whose full scale is `rangeMetres`: rounded
// down, so the decoded distance (code - 128) / 127 x range never exceeds it.
std::uint8_t heroDistanceCode(float metres, float rangeMetres);
// The atlas of `assets` (each valid: validateNvdf()).
HeroAtlasLayout packHeroAtlas(std::span<const NvdfVolume* const> assets);

// What a cloud's life (HeroCloud::growth, ::dissipation) makes of its instance: the uniforms
// cloud_hero.h's heroLifeWeight() reads. Both eased (smoothstep), so a life that changes at a
// steady rate starts and stops gently.
struct HeroLifeShape {
  float topIndex = 0.0f;       // index y above which the cloud's edge is not (yet) grown
  float erosionMetres = 0.0f;  // world metres eaten from its edge inwards
  float densityFactor = 1.0f;  // its density, faded as it dissipates
};
// Erosion, as fractions of the distance code's full scale (kHeroDistanceRangeVoxels): a newborn
// cloud is its thickest cores; a dissipating one thins from its edge in. Kept below the full
// scale: there every deep voxel reads the same distance, and the whole core would go within one
// voxel of erosion instead of fading last.
inline constexpr float kGrowthErosion = 0.5f;
inline constexpr float kDissipationErosion = 0.75f;
inline constexpr float kMostErosion = 0.9f;
HeroLifeShape heroLifeShape(const HeroCloud& cloud, float heightVoxels, float voxelWorldMetres);

// This frame's instances as the march reads them: camera-relative, in double precision. A
// cloud its life leaves empty (growth 0, or dissipation 1) is left out.
shader::HeroCloudUniforms heroCloudUniforms(const std::vector<HeroAsset>& assets,
                                            std::span<const HeroCloud> clouds,
                                            const glm::dvec3& cameraPosition);

// The variant (shader::kHeroClouds*) that draws `block`: kHeroCloudsLiving when one of its
// clouds grows or dissipates (its erosion is not 0), else kHeroCloudsAuthored.
std::uint32_t heroCloudVariant(const shader::HeroCloudUniforms& block);

// Whether the camera (the block's origin) lies in one of its instances' boxes, or within
// `marginMetres` of one.
bool cameraInHeroCloudBox(const shader::HeroCloudUniforms& block, float marginMetres);

// The atlas image and its upload.
class HeroCloudAtlas {
 public:
  // Creates the image and a staging buffer holding its texels (the next frame copies them).
  HeroCloudAtlas(const DeviceContext& device, HeroAtlasLayout layout);

  const std::vector<HeroAsset>& assets() const { return assets_; }
  const OwnedImage& image() const { return image_; }
  // Records the copy into the image and its transition to GENERAL for the march's reads, once.
  void recordUpload(VkCommandBuffer cmd, std::uint64_t frameIndex);
  // Frees the staging buffer once the frame that copied it cannot be in flight any more.
  void releaseStaging(std::uint64_t frameIndex, std::uint32_t framesInFlight);
  VkDeviceSize bytes() const { return image_.bytes() + staging_.bytes(); }

 private:
  const DeviceContext* device_;
  std::vector<HeroAsset> assets_;
  OwnedImage image_;
  OwnedBuffer staging_;
  std::optional<std::uint64_t> uploadFrame_;
};

}  // namespace clouds::detail
