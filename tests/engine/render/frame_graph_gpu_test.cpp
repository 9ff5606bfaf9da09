// Executing a compiled frame graph on the device: results are right, barriers are
// validation-clean (the fixture fails on any message), and per-pass GPU timings come back.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "engine/gfx/descriptors.h"
#include "engine/gfx/frame_ring.h"
#include "engine/gfx/pipelines.h"
#include "engine/render/frame_graph.h"
#include "gpu_test.h"
#include "render_test_shaders/fill.comp.spv.h"
#include "render_test_shaders/invert.comp.spv.h"

namespace {

using namespace engine;
using namespace engine::render;

class FrameGraphGpu : public test::GpuTest {};

struct Pipelines {
  gfx::Pipeline fill;
  gfx::Pipeline invert;
  gfx::Sampler sampler;
  explicit Pipelines(gfx::Device& device)
      : sampler(device, gfx::SamplerDesc{VK_FILTER_NEAREST, VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                         VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "test sampler"}) {
    gfx::ComputePipelineDesc f;
    f.spirv = fill_comp_spv;
    f.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_FORMAT_R8G8B8A8_UNORM}};
    f.pushConstantBytes = 8;
    f.debugName = "fill";
    fill = gfx::Pipeline(device, f);
    gfx::ComputePipelineDesc i;
    i.spirv = invert_comp_spv;
    i.bindings = {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_FORMAT_R8G8B8A8_UNORM},
                  {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_FORMAT_R8G8B8A8_UNORM}};
    i.pushConstantBytes = 8;
    i.debugName = "invert";
    invert = gfx::Pipeline(device, i);
  }
};

void buildGraph(FrameGraph& graph, const Pipelines& p, VkExtent2D extent,
                const gfx::Buffer& readback) {
  TextureDesc desc;
  desc.extent = {extent.width, extent.height, 1};
  desc.format = VK_FORMAT_R8G8B8A8_UNORM;
  const ResourceState host{VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_HOST_BIT,
                           VK_ACCESS_2_HOST_READ_BIT};
  BufferHandle out =
      graph.importBuffer("readback", ImportedBuffer{readback.vk(), readback.size(), host, host});
  struct FillData {
    TextureHandle target;
  };
  const auto& fill = graph.addPass<FillData>(
      "fill", PassType::Compute,
      [&](PassBuilder& b, FillData& d) {
        d.target = b.write(b.createTexture("filled", desc), Access::StorageWrite);
      },
      [&p](const FillData& d, PassContext& ctx) {
        gfx::DescriptorWriter w;
        w.storageImage(0, ctx.view(d.target));
        ctx.bind(p.fill, w);
        const VkExtent3D e = ctx.extent(d.target);
        const std::uint32_t size[2] = {e.width, e.height};
        vkCmdPushConstants(ctx.cmd(), p.fill.layout(), p.fill.pushConstantStages(), 0, 8, size);
        vkCmdDispatch(ctx.cmd(), gfx::groupCount(e.width, 8), gfx::groupCount(e.height, 8), 1);
      });
  struct InvertData {
    TextureHandle source, target;
  };
  const auto& invert = graph.addPass<InvertData>(
      "invert", PassType::Compute,
      [&](PassBuilder& b, InvertData& d) {
        d.source = b.read(fill.target, Access::SampledRead);
        d.target = b.write(b.createTexture("inverted", desc), Access::StorageWrite);
      },
      [&p](const InvertData& d, PassContext& ctx) {
        gfx::DescriptorWriter w;
        w.combinedImageSampler(0, ctx.view(d.source), p.sampler.vk());
        w.storageImage(1, ctx.view(d.target));
        ctx.bind(p.invert, w);
        const VkExtent3D e = ctx.extent(d.target);
        const std::uint32_t size[2] = {e.width, e.height};
        vkCmdPushConstants(ctx.cmd(), p.invert.layout(), p.invert.pushConstantStages(), 0, 8, size);
        vkCmdDispatch(ctx.cmd(), gfx::groupCount(e.width, 8), gfx::groupCount(e.height, 8), 1);
      });
  struct CopyData {
    TextureHandle source;
    BufferHandle out;
  };
  graph.addPass<CopyData>(
      "copy out", PassType::Transfer,
      [&](PassBuilder& b, CopyData& d) {
        d.source = b.read(invert.target, Access::TransferSrc);
        d.out = b.write(out, Access::TransferDst);
      },
      [](const CopyData& d, PassContext& ctx) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = ctx.extent(d.source);
        vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(d.source), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               ctx.buffer(d.out), 1, &region);
      });
  graph.compile();
}

void expectInverted(const gfx::Buffer& readback, VkExtent2D extent) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(readback.mapped());
  for (std::uint32_t y = 0; y < extent.height; ++y) {
    for (std::uint32_t x = 0; x < extent.width; ++x) {
      const std::uint8_t* p = bytes + 4 * (y * extent.width + x);
      ASSERT_EQ(p[0], 255 - x) << x << "," << y;
      ASSERT_EQ(p[1], 255 - y);
      ASSERT_EQ(p[2], 245);
    }
  }
}

TEST_F(FrameGraphGpu, ExecutesComputeChainsAcrossFramesAndRebuilds) {
  Pipelines pipelines(device());
  gfx::FrameRing ring(device());
  for (const VkExtent2D extent : {VkExtent2D{40, 24}, VkExtent2D{17, 9}}) {
    gfx::Buffer readback(device(), gfx::BufferDesc{4ull * extent.width * extent.height,
                                                   VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                   gfx::MemoryUsage::Readback, "test readback"});
    FrameGraph graph(&device());
    buildGraph(graph, pipelines, extent, readback);
    for (int frame = 0; frame < 3; ++frame) {
      std::memset(readback.mapped(), 0, readback.size());
      auto& f = ring.begin();
      graph.execute(f);
      ring.submit();
      ring.drain();
      expectInverted(readback, extent);
    }
    std::vector<std::string> timed;
    for (const auto& scope : ring.lastTimings()) timed.emplace_back(scope.name);
    EXPECT_EQ(timed, (std::vector<std::string>{"fill", "invert", "copy out"}));
  }
}

}  // namespace
