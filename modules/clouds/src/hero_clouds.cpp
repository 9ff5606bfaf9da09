#include "hero_clouds.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace clouds::detail {

static_assert(kMaxHeroClouds == shader::kMaxHeroClouds, "the API's bound is the block's");

std::uint8_t heroDistanceCode(float metres, float rangeMetres) {
  const double code = std::floor(double(metres) / double(rangeMetres) * 127.0) + 128.0;
  return static_cast<std::uint8_t>(std::clamp(code, 0.0, 255.0));
}

HeroAtlasLayout packHeroAtlas(std::span<const NvdfVolume* const> assets) {
  // The two stackings' extents: along z and along x.
  glm::uvec3 alongZ(0u), alongX(0u);
  for (const NvdfVolume* asset : assets) {
    alongZ = glm::uvec3(std::max(alongZ.x, asset->size.x), std::max(alongZ.y, asset->size.y),
                        alongZ.z + asset->size.z);
    alongX = glm::uvec3(alongX.x + asset->size.x, std::max(alongX.y, asset->size.y),
                        std::max(alongX.z, asset->size.z));
  }
  const auto texels = [](const glm::uvec3& e) { return std::uint64_t{e.x} * e.y * e.z; };
  const bool stackAlongX = texels(alongX) < texels(alongZ);
  const glm::uvec3 extent = stackAlongX ? alongX : alongZ;
  HeroAtlasLayout layout;
  layout.extent = {extent.x, extent.y, extent.z};
  std::uint32_t next = 0;
  for (const NvdfVolume* asset : assets) {
    HeroAsset placed;
    placed.size = asset->size;
    placed.atlasOrigin = stackAlongX ? glm::uvec3(next, 0u, 0u) : glm::uvec3(0u, 0u, next);
    placed.voxelMetres = asset->voxelMetres;
    placed.originMetres = asset->originMetres;
    placed.densityMultiplier = asset->densityMultiplier;
    layout.assets.push_back(placed);
    next += stackAlongX ? asset->size.x : asset->size.z;
  }
  const std::size_t row = layout.extent.width;
  const std::size_t slice = row * layout.extent.height;
  layout.texels.assign(4 * slice * layout.extent.depth, 0);
  for (std::size_t a = 0; a < assets.size(); ++a) {
    const NvdfVolume& v = *assets[a];
    const float range = shader::kHeroDistanceRangeVoxels * v.voxelMetres;
    const glm::uvec3 origin = layout.assets[a].atlasOrigin;
    for (std::uint32_t z = 0; z < v.size.z; ++z) {
      for (std::uint32_t y = 0; y < v.size.y; ++y) {
        for (std::uint32_t x = 0; x < v.size.x; ++x) {
          const glm::uvec3 voxel(x, y, z);
          const std::uint8_t* fields = &v.fields[v.voxelIndex(voxel) * kNvdfChannels];
          std::uint8_t* texel =
              &layout.texels[4 * ((origin.z + z) * slice + y * row + origin.x + x)];
          texel[0] = fields[kNvdfProfile];
          texel[1] = fields[kNvdfDetailType];
          texel[2] = fields[kNvdfDensityScale];
          texel[3] = heroDistanceCode(v.distanceMetres(voxel), range);
        }
      }
    }
  }
  return layout;
}

HeroLifeShape heroLifeShape(const HeroCloud& cloud, float heightVoxels, float voxelWorldMetres) {
  const auto ease = [](float x) { return x * x * (3.0f - 2.0f * x); };
  const float grown = ease(std::clamp(cloud.growth, 0.0f, 1.0f));
  const float gone = ease(std::clamp(cloud.dissipation, 0.0f, 1.0f));
  const float feather = std::max(shader::kHeroTopFeather * heightVoxels, 1.0f);
  const float depthScale = shader::kHeroDistanceRangeVoxels * voxelWorldMetres;
  HeroLifeShape shape;
  // The top rises from so far below the box (-1, where the filter's reach starts) that not even
  // its deepest points (kHeroDistanceRangeVoxels) stand above it, to a feather above its last
  // voxels, where heroLifeWeight() reads 1 throughout.
  const float lowest = -1.0f - shader::kHeroDistanceRangeVoxels;
  shape.topIndex = lowest + grown * (heightVoxels + feather - lowest);
  shape.erosionMetres =
      std::min((1.0f - grown) * kGrowthErosion + gone * kDissipationErosion, kMostErosion) *
      depthScale;
  shape.densityFactor = 1.0f - gone;
  return shape;
}

shader::HeroCloudUniforms heroCloudUniforms(const std::vector<HeroAsset>& assets,
                                            std::span<const HeroCloud> clouds,
                                            const glm::dvec3& cameraPosition) {
  shader::HeroCloudUniforms block{};
  for (const HeroCloud& cloud : clouds) {
    if (!(cloud.growth > 0.0f && cloud.dissipation < 1.0f)) continue;
    const HeroAsset& asset = assets[cloud.asset];
    // world = R (local x scale) + position, R a turn about +y; so
    // index = (R^T (world - position) / scale - origin) / voxel, made camera-relative.
    const double c = std::cos(double(cloud.yawRadians));
    const double s = std::sin(double(cloud.yawRadians));
    const glm::dmat3 turn(glm::dvec3(c, 0.0, -s), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(s, 0.0, c));
    const double perMetre = 1.0 / (double(cloud.scale) * double(asset.voxelMetres));
    const glm::dmat3 toIndex = glm::transpose(turn) * perMetre;
    const glm::dvec3 offset = -(toIndex * (cloud.positionMetres - cameraPosition)) -
                              glm::dvec3(asset.originMetres) / double(asset.voxelMetres);
    shader::HeroCloudInstance& h = block.instance[block.count.x++];
    for (int row = 0; row < 3; ++row) {
      // glm is column-major: toIndex[column][row].
      h.toIndex[row] = glm::vec4(float(toIndex[0][row]), float(toIndex[1][row]),
                                 float(toIndex[2][row]), float(offset[row]));
    }
    h.extent = glm::vec4(
        glm::vec3(asset.size),
        float(asset.atlasOrigin.x * shader::kHeroAtlasOriginStride + asset.atlasOrigin.z));
    const float voxelWorld = asset.voxelMetres * cloud.scale;
    const HeroLifeShape life = heroLifeShape(cloud, float(asset.size.y), voxelWorld);
    h.scales = glm::vec4(asset.densityMultiplier * life.densityFactor, life.erosionMetres,
                         voxelWorld, life.topIndex);
  }
  return block;
}

std::uint32_t heroCloudVariant(const shader::HeroCloudUniforms& block) {
  for (std::uint32_t i = 0; i < block.count.x; ++i) {
    if (block.instance[i].scales.y > 0.0f) return shader::kHeroCloudsLiving;
  }
  return shader::kHeroCloudsAuthored;
}

bool cameraInHeroCloudBox(const shader::HeroCloudUniforms& block, float marginMetres) {
  for (std::uint32_t i = 0; i < block.count.x; ++i) {
    const shader::HeroCloudInstance& h = block.instance[i];
    // The camera is the origin of camera-relative space: its index coordinate is the offset.
    const glm::vec3 camera(h.toIndex[0].w, h.toIndex[1].w, h.toIndex[2].w);
    const float margin = marginMetres / h.scales.z;
    const glm::vec3 low(-1.0f - margin);
    const glm::vec3 high = glm::vec3(h.extent) + margin;
    if (glm::all(glm::greaterThanEqual(camera, low)) &&
        glm::all(glm::lessThanEqual(camera, high))) {
      return true;
    }
  }
  return false;
}

HeroCloudAtlas::HeroCloudAtlas(const DeviceContext& device, HeroAtlasLayout layout)
    : device_(&device),
      assets_(std::move(layout.assets)),
      image_(device, VK_IMAGE_TYPE_3D, VK_FORMAT_R8G8B8A8_UNORM, layout.extent,
             VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "hero cloud atlas"),
      staging_(device, layout.texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
               "hero cloud atlas upload", /*hostVisible=*/true) {
  std::memcpy(staging_.mapped(), layout.texels.data(), layout.texels.size());
}

void HeroCloudAtlas::recordUpload(VkCommandBuffer cmd, std::uint64_t frameIndex) {
  if (uploadFrame_) return;
  barrier(*device_, cmd, image_.image(), VK_IMAGE_LAYOUT_UNDEFINED,
          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
          VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = image_.extent();
  device_->fn().vkCmdCopyBufferToImage(cmd, staging_.buffer(), image_.image(),
                                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  barrier(*device_, cmd, image_.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
          VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
          kComputeStage, kStorageRead);
  uploadFrame_ = frameIndex;
}

void HeroCloudAtlas::releaseStaging(std::uint64_t frameIndex, std::uint32_t framesInFlight) {
  if (uploadFrame_ && staging_.size() > 0 && frameIndex >= *uploadFrame_ + framesInFlight) {
    staging_ = OwnedBuffer();
  }
}

}  // namespace clouds::detail
