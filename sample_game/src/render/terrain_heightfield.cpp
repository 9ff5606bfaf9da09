#include "render/terrain_heightfield.h"

#include <cstdint>
#include <glm/gtc/packing.hpp>
#include <span>
#include <vector>

#include "engine/gfx/upload.h"
#include "game/terrain_height.h"

namespace sample {

namespace {

// R32F keeps the altitudes exactly; it filters linearly on most devices (lavapipe, desktop
// GPUs), R16F (0.5 m steps at 1 km, 2 m at 3 km) on every device.
VkFormat heightFormat(const engine::gfx::Device& device) {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(device.physical(), VK_FORMAT_R32_SFLOAT, &properties);
  return (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT)
             ? VK_FORMAT_R32_SFLOAT
             : VK_FORMAT_R16_SFLOAT;
}

}  // namespace

TerrainHeightfieldImage::TerrainHeightfieldImage(engine::gfx::Device& device,
                                                 const engine::assets::MeshData& mesh) {
  const SurfaceHeights surface = sampleSurface(mesh, kResolution);
  const VkFormat format = heightFormat(device);
  std::vector<std::uint16_t> halves;
  if (format == VK_FORMAT_R16_SFLOAT) {
    halves.reserve(surface.metres.size());
    for (float h : surface.metres) halves.push_back(glm::packHalf1x16(h));
  }
  image_ = engine::gfx::Image(
      device, engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                     format,
                                     {kResolution, kResolution, 1},
                                     1,
                                     1,
                                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     "terrain heightfield"});
  const std::span<const std::byte> texels = format == VK_FORMAT_R16_SFLOAT
                                                ? std::as_bytes(std::span(halves))
                                                : std::as_bytes(std::span(surface.metres));
  engine::gfx::uploadToImage(device, image_, texels,
                             engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  description_.view = image_.view();
  description_.originMetres = surface.originMetres;
  description_.sizeMetres = surface.sizeMetres;
  description_.minAltitudeMetres = surface.minMetres;
  description_.maxAltitudeMetres = surface.maxMetres;
}

}  // namespace sample
