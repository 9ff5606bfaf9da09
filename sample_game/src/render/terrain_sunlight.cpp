#include "render/terrain_sunlight.h"

#include <algorithm>
#include <vector>

#include "bindings.h"
#include "engine/core/error.h"
#include "engine/gfx/descriptors.h"
#include "engine/gfx/upload.h"
#include "fxcontracts/ecs/frame_entries.h"
#include "sample_shaders/terrain_sunlight.comp.spv.h"
#include "terrain_sunlight_map.h"

namespace sample {

using namespace engine;

namespace {

using shaders::kSunlightCloudShadowBinding;
using shaders::kSunlightHeightfieldBinding;
using shaders::kSunlightMapBinding;
using shaders::kSunlightShadowParametersBinding;

// Where the map is between frames: the scene pass's fragment shaders read it last.
const render::ResourceState kReadByTheScene{VK_IMAGE_LAYOUT_GENERAL,
                                            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};

void requireFormat(const gfx::Device& device) {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(device.physical(), TerrainSunlight::kFormat, &properties);
  const VkFormatFeatureFlags needed =
      VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((properties.optimalTilingFeatures & needed) != needed) {
    throw Error("the terrain's sunlight map needs R16_SFLOAT as a filtered, storage image");
  }
}

}  // namespace

TerrainSunlight::TerrainSunlight(gfx::Device& device, const render::TerrainHeightfield& heightfield,
                                 std::uint32_t resolution)
    : heightfield_(heightfield), resolution_(resolution), schedule_(resolution, kRefreshFrames) {
  requireFormat(device);
  image_ =
      gfx::Image(device, gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                        kFormat,
                                        {resolution, resolution, 1},
                                        1,
                                        1,
                                        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                            VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                        "terrain sunlight"});
  // Full sun until the first refresh (which makes the whole map before anything reads it).
  const std::uint16_t kOneHalf = 0x3c00;
  const std::vector<std::uint16_t> ones(std::size_t{resolution} * resolution, kOneHalf);
  gfx::uploadToImage(
      device, image_, std::as_bytes(std::span(ones)),
      gfx::ImageState{kReadByTheScene.layout, kReadByTheScene.stages, kReadByTheScene.access});
  gfx::SamplerDesc clamped;
  clamped.debugName = "terrain sunlight linear clamped";
  sampler_ = gfx::Sampler(device, clamped);

  gfx::ComputePipelineDesc desc;
  desc.spirv = terrain_sunlight_comp_spv;
  desc.bindings = {{kSunlightHeightfieldBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                    VK_FORMAT_R32_SFLOAT},
                   {kSunlightCloudShadowBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                    VK_FORMAT_R16G16B16A16_SFLOAT},
                   {kSunlightShadowParametersBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                   {kSunlightMapBinding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kFormat}};
  desc.pushConstantBytes = sizeof(shaders::TerrainSunlightConstants);
  desc.debugName = "terrain sunlight";
  pipeline_ = gfx::Pipeline(device, desc);
}

glm::vec4 TerrainSunlight::placementFor(const glm::dvec3& cameraPosition) const {
  const glm::dvec2 camera(cameraPosition.x, cameraPosition.z);
  const glm::dvec2 uv = (camera - heightfield_.originMetres) / heightfield_.sizeMetres;
  const glm::dvec2 reciprocal = 1.0 / heightfield_.sizeMetres;
  return glm::vec4(glm::vec2(uv), glm::vec2(reciprocal));
}

render::TextureHandle TerrainSunlight::addLitPass(render::FrameGraph& graph,
                                                  render::TextureHandle map) {
  struct Data {
    render::TextureHandle map;
  };
  litPassInGraph_ = true;
  const Data& data = graph.addPass<Data>(
      "terrain sunlight lit", render::PassType::Transfer,
      [&](render::PassBuilder& builder, Data& d) {
        d.map = builder.write(map, render::Access::TransferDst);
      },
      [this](const Data& d, render::PassContext& context) {
        if (lit_) return;
        const VkClearColorValue fullSun{{1.0f, 1.0f, 1.0f, 1.0f}};
        const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(context.cmd(), context.image(d.map),
                             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &fullSun, 1, &all);
        lit_ = true;
      });
  return data.map;
}

TerrainSunlightSchedule::TerrainSunlightSchedule(std::uint32_t rows, std::uint32_t frames)
    : rows_(rows),
      rowsPerBand_((rows + std::max(frames, 1u) - 1) / std::max(frames, 1u)),
      bands_((rows + rowsPerBand_ - 1) / std::max(rowsPerBand_, 1u)) {}

TerrainSunlightSchedule::Rows TerrainSunlightSchedule::next(bool shadowMapRemadeWhole) {
  if (!filled_ || shadowMapRemadeWhole) {
    filled_ = true;
    band_ = 0;
    return {0, rows_};
  }
  const std::uint32_t first = band_ * rowsPerBand_;
  band_ = (band_ + 1) % bands_;
  return {first, std::min(rowsPerBand_, rows_ - first)};
}

render::TextureHandle TerrainSunlight::addPass(render::FrameGraph& graph,
                                               const glm::dvec3* cameraPosition) {
  render::ImportedTexture imported;
  imported.image = image_.vk();
  imported.view = image_.view();
  imported.desc.extent = {resolution_, resolution_, 1};
  imported.desc.format = kFormat;
  imported.initial = kReadByTheScene;
  imported.final = kReadByTheScene;
  const render::TextureHandle map = graph.importTexture("terrain sunlight", imported);
  const auto* cloudShadow = graph.blackboard().find<fxcontracts::ecs::CloudShadow>();
  litPassInGraph_ = false;
  if (cloudShadow == nullptr) return lit_ ? map : addLitPass(graph, map);
  if (lit_) {
    // Shadows again: the whole map at the first refresh.
    schedule_ = TerrainSunlightSchedule(resolution_, kRefreshFrames);
    lit_ = false;
  }
  struct Data {
    render::TextureHandle cloudShadow;
    render::TextureHandle map;
  };
  const Data& data = graph.addPass<Data>(
      "terrain sunlight", render::PassType::Compute,
      [&](render::PassBuilder& builder, Data& d) {
        d.cloudShadow = builder.read(cloudShadow->map, render::Access::SampledReadGeneral);
        d.map = builder.write(map, render::Access::StorageWrite);
      },
      [this, cameraPosition](const Data& d, render::PassContext& context) {
        // The map's pass has executed: this frame's parameters are filled.
        const auto& shadow = context.blackboard().get<fxcontracts::ecs::CloudShadow>();
        const TerrainSunlightSchedule::Rows rows = schedule_.next(shadow.remadeWhole);
        const gfx::ConstantRing::Slice block = context.constants().push(shadow.parameters);
        gfx::DescriptorWriter writer;
        writer.combinedImageSampler(kSunlightHeightfieldBinding, heightfield_.view, sampler_.vk());
        writer.combinedImageSampler(kSunlightCloudShadowBinding, context.view(d.cloudShadow),
                                    sampler_.vk(), VK_IMAGE_LAYOUT_GENERAL);
        writer.uniformBuffer(kSunlightShadowParametersBinding, block.buffer, block.offset,
                             block.size);
        writer.storageImage(kSunlightMapBinding, context.view(d.map));
        context.bind(pipeline_, writer);
        const glm::dvec2 texel = heightfield_.sizeMetres / double(resolution_);
        shaders::TerrainSunlightConstants constants{};
        constants.cornerRelative =
            glm::vec2(heightfield_.originMetres - glm::dvec2(cameraPosition->x, cameraPosition->z));
        constants.texelMetres = glm::vec2(texel);
        constants.resolution = resolution_;
        constants.firstRow = rows.first;
        constants.rowCount = rows.count;
        vkCmdPushConstants(context.cmd(), pipeline_.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           sizeof(constants), &constants);
        vkCmdDispatch(context.cmd(),
                      gfx::groupCount(resolution_, shaders::kTerrainSunlightGroupSize),
                      gfx::groupCount(rows.count, shaders::kTerrainSunlightGroupSize), 1);
      });
  return data.map;
}

}  // namespace sample
