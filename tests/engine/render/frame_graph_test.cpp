// Frame-graph compilation without a device: ordering, culling, versioning and barriers.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.h"
#include "engine/render/frame_graph.h"

namespace {

using namespace engine::render;

struct Empty {};
const auto kNoExecute = [](const Empty&, PassContext&) {};

TextureDesc colour(VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT) {
  TextureDesc desc;
  desc.extent = {64, 32, 1};
  desc.format = format;
  return desc;
}

ImportedTexture presentable() {
  ImportedTexture texture;
  texture.desc = colour(VK_FORMAT_B8G8R8A8_SRGB);
  texture.initial = {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_NONE};
  texture.final = ResourceState{VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                                VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_NONE};
  return texture;
}

std::vector<std::string> names(const std::vector<const char*>& list) {
  return {list.begin(), list.end()};
}

// sky (compute) -> scene (graphics, depth) -> tonemap (graphics) -> backbuffer; plus a debug
// pass whose output nobody reads and a readback with a side effect.
struct TypicalFrame {
  FrameGraph graph;
  TextureHandle backbuffer;
  TypicalFrame() {
    backbuffer = graph.importTexture("backbuffer", presentable());
    TextureHandle hdr;
    graph.addPass<Empty>(
        "sky", PassType::Compute,
        [&](PassBuilder& b, Empty&) {
          hdr = b.createTexture("hdr", colour());
          hdr = b.write(hdr, Access::StorageWrite);
        },
        kNoExecute);
    TextureHandle depth;
    graph.addPass<Empty>(
        "debug overlay", PassType::Compute,
        [&](PassBuilder& b, Empty&) {
          b.read(hdr, Access::SampledRead);
          TextureHandle debug = b.createTexture("debug", colour());
          b.write(debug, Access::StorageWrite);
        },
        kNoExecute);
    graph.addPass<Empty>(
        "scene", PassType::Graphics,
        [&](PassBuilder& b, Empty&) {
          depth = b.createTexture("depth", colour(VK_FORMAT_D32_SFLOAT));
          depth = b.depthAttachment(depth, VK_ATTACHMENT_LOAD_OP_CLEAR);
          hdr = b.colorAttachment(hdr, VK_ATTACHMENT_LOAD_OP_LOAD);
        },
        kNoExecute);
    graph.addPass<Empty>(
        "tonemap", PassType::Graphics,
        [&](PassBuilder& b, Empty&) {
          b.read(hdr, Access::SampledRead);
          backbuffer = b.colorAttachment(backbuffer, VK_ATTACHMENT_LOAD_OP_DONT_CARE);
        },
        kNoExecute);
    graph.addPass<Empty>(
        "readback", PassType::Transfer,
        [&](PassBuilder& b, Empty&) {
          b.read(backbuffer, Access::TransferSrc);
          b.sideEffect();
        },
        kNoExecute);
  }
};

TEST(FrameGraph, OrdersByDependenciesAndCullsUnreadOutputs) {
  TypicalFrame frame;
  frame.graph.compile();
  EXPECT_EQ(names(frame.graph.executionOrder()),
            (std::vector<std::string>{"sky", "scene", "tonemap", "readback"}));
  EXPECT_EQ(names(frame.graph.culledPasses()), std::vector<std::string>{"debug overlay"});
}

TEST(FrameGraph, CullingPropagatesThroughChains) {
  FrameGraph graph;
  TextureHandle a, b;
  graph.addPass<Empty>(
      "producer", PassType::Compute,
      [&](PassBuilder& pb, Empty&) {
        a = pb.write(pb.createTexture("a", colour()), Access::StorageWrite);
      },
      kNoExecute);
  graph.addPass<Empty>(
      "consumer", PassType::Compute,
      [&](PassBuilder& pb, Empty&) {
        pb.read(a, Access::SampledRead);
        b = pb.write(pb.createTexture("b", colour()), Access::StorageWrite);
      },
      kNoExecute);
  graph.addPass<Empty>(
      "kept", PassType::Compute, [&](PassBuilder& pb, Empty&) { pb.sideEffect(); }, kNoExecute);
  graph.compile();
  EXPECT_EQ(names(graph.executionOrder()), std::vector<std::string>{"kept"});
  EXPECT_EQ(names(graph.culledPasses()), (std::vector<std::string>{"producer", "consumer"}));
}

TEST(FrameGraph, OrderRespectsWriteAfterReadAndDeclarationOrderOtherwise) {
  // "reader" reads version 1 of history; "updater" writes version 2; the graph must run the
  // reader first even though both could start. "independent" keeps its declaration slot.
  FrameGraph graph;
  ImportedTexture historyDesc;
  historyDesc.desc = colour();
  historyDesc.initial = {VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                         VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
  historyDesc.final = ResourceState{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
  TextureHandle history = graph.importTexture("history", historyDesc);
  graph.addPass<Empty>(
      "reader", PassType::Compute,
      [&](PassBuilder& b, Empty&) {
        b.read(history, Access::StorageRead);
        b.sideEffect();
      },
      kNoExecute);
  graph.addPass<Empty>(
      "independent", PassType::Compute, [&](PassBuilder& b, Empty&) { b.sideEffect(); },
      kNoExecute);
  graph.addPass<Empty>(
      "updater", PassType::Compute,
      [&](PassBuilder& b, Empty&) { history = b.write(history, Access::StorageWrite); },
      kNoExecute);
  graph.compile();
  EXPECT_EQ(names(graph.executionOrder()),
            (std::vector<std::string>{"reader", "independent", "updater"}));
  // The write after a read in the same layout needs an execution dependency on the read.
  const auto barriers = graph.barriersBefore("updater");
  ASSERT_EQ(barriers.size(), 1u);
  EXPECT_TRUE(barriers[0].from.stages & VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
  EXPECT_EQ(barriers[0].from.layout, VK_IMAGE_LAYOUT_GENERAL);
}

TEST(FrameGraph, BarriersTransitionLayoutsAndMakeWritesVisible) {
  TypicalFrame frame;
  frame.graph.compile();
  const auto& g = frame.graph;

  // sky: first use of a transient -> UNDEFINED to GENERAL, nothing to wait for.
  auto sky = g.barriersBefore("sky");
  ASSERT_EQ(sky.size(), 1u);
  EXPECT_EQ(sky[0].from.layout, VK_IMAGE_LAYOUT_UNDEFINED);
  EXPECT_EQ(sky[0].to.layout, VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_EQ(sky[0].from.stages, VK_PIPELINE_STAGE_2_NONE);

  // scene: hdr GENERAL -> COLOR_ATTACHMENT after the compute write; depth UNDEFINED -> DEPTH.
  auto scene = g.barriersBefore("scene");
  ASSERT_EQ(scene.size(), 2u);
  bool sawHdr = false, sawDepth = false;
  for (const auto& b : scene) {
    const std::string name = g.resourceName(b.resource);
    if (name == "hdr") {
      sawHdr = true;
      EXPECT_EQ(b.from.layout, VK_IMAGE_LAYOUT_GENERAL);
      EXPECT_EQ(b.to.layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
      EXPECT_EQ(b.from.stages, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
      EXPECT_TRUE(b.from.access & VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }
    if (name == "depth") {
      sawDepth = true;
      EXPECT_EQ(b.to.layout, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    }
  }
  EXPECT_TRUE(sawHdr && sawDepth);

  // tonemap: hdr to SHADER_READ_ONLY after the colour write; backbuffer waits on the acquire
  // stage before leaving UNDEFINED.
  auto tonemap = g.barriersBefore("tonemap");
  ASSERT_EQ(tonemap.size(), 2u);
  for (const auto& b : tonemap) {
    const std::string name = g.resourceName(b.resource);
    if (name == "hdr") {
      EXPECT_EQ(b.to.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
      EXPECT_EQ(b.from.stages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
      EXPECT_TRUE(b.to.stages & VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    } else {
      EXPECT_EQ(name, "backbuffer");
      EXPECT_EQ(b.from.stages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
      EXPECT_EQ(b.to.layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    }
  }

  // The backbuffer ends in PRESENT_SRC after the readback's transfer read.
  ASSERT_EQ(g.finalBarriers().size(), 1u);
  EXPECT_EQ(g.finalBarriers()[0].from.layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  EXPECT_EQ(g.finalBarriers()[0].to.layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
}

TEST(FrameGraph, ReadsInANewStageOfTheSameLayoutStillWaitForTheWrite) {
  FrameGraph graph;
  TextureHandle t;
  graph.addPass<Empty>(
      "write", PassType::Compute,
      [&](PassBuilder& b, Empty&) {
        t = b.write(b.createTexture("t", colour()), Access::StorageWrite);
      },
      kNoExecute);
  graph.addPass<Empty>(
      "sample in fragment", PassType::Graphics,
      [&](PassBuilder& b, Empty&) {
        b.read(t, Access::SampledRead);
        b.sideEffect();
      },
      kNoExecute);
  graph.addPass<Empty>(
      "sample in fragment again", PassType::Graphics,
      [&](PassBuilder& b, Empty&) {
        b.read(t, Access::SampledRead);
        b.sideEffect();
      },
      kNoExecute);
  graph.addPass<Empty>(
      "sample in compute", PassType::Compute,
      [&](PassBuilder& b, Empty&) {
        b.read(t, Access::SampledRead);
        b.sideEffect();
      },
      kNoExecute);
  graph.compile();
  EXPECT_EQ(graph.barriersBefore("sample in fragment").size(), 1u);
  EXPECT_EQ(graph.barriersBefore("sample in fragment again").size(), 0u) << "already visible";
  const auto compute = graph.barriersBefore("sample in compute");
  ASSERT_EQ(compute.size(), 1u) << "the compute stage has not been made to see the write";
  // The layout transition to SHADER_READ_ONLY completed before the graphics shader stages, so
  // the compute read chains from there (and through them from the original compute write).
  EXPECT_EQ(compute[0].from.stages,
            VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
  EXPECT_EQ(compute[0].to.stages, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
}

TEST(FrameGraph, StaleVersionsAndMisuseAreRejected) {
  FrameGraph graph;
  TextureHandle v0, v1;
  graph.addPass<Empty>(
      "first", PassType::Compute,
      [&](PassBuilder& b, Empty&) {
        v0 = b.createTexture("t", colour());
        v1 = b.write(v0, Access::StorageWrite);
      },
      kNoExecute);
  EXPECT_THROW(graph.addPass<Empty>(
                   "stale", PassType::Compute,
                   [&](PassBuilder& b, Empty&) { b.read(v0, Access::SampledRead); }, kNoExecute),
               engine::Error);
  EXPECT_THROW(
      graph.addPass<Empty>(
          "compute attachment", PassType::Compute,
          [&](PassBuilder& b, Empty&) { b.colorAttachment(v1, VK_ATTACHMENT_LOAD_OP_LOAD); },
          kNoExecute),
      engine::Error);
  EXPECT_THROW(graph.addPass<Empty>(
                   "write as read", PassType::Compute,
                   [&](PassBuilder& b, Empty&) { b.read(v1, Access::StorageWrite); }, kNoExecute),
               engine::Error);
}

}  // namespace
