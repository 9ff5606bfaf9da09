// GPU compute: dispatches read back and compared with the same computation on the CPU.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "engine/gfx/barriers.h"
#include "engine/gfx/descriptors.h"
#include "engine/gfx/gpu_timer.h"
#include "engine/gfx/pipelines.h"
#include "engine/gfx/resources.h"
#include "engine/gfx/upload.h"
#include "gfx_test_shaders/image_pattern.comp.spv.h"
#include "gfx_test_shaders/math_probe.comp.spv.h"
#include "gpu_test.h"

namespace {

using namespace engine::gfx;

float cpuProbe(std::uint32_t i, float scale) {
  const float x = static_cast<float>(i) * 0.01f;
  return scale * (std::sin(x) * x + std::sqrt(x) + std::exp(-x));
}

class Compute : public test::GpuTest {};

std::vector<float> runMathProbe(Device& device, std::uint32_t count, float scale,
                                GpuTimer* timer = nullptr) {
  ComputePipelineDesc desc;
  desc.spirv = math_probe_comp_spv;
  desc.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  desc.pushConstantBytes = sizeof(std::uint32_t);
  std::uint32_t scaleBits = 0;
  std::memcpy(&scaleBits, &scale, sizeof(float));
  desc.specialization = {{0, scaleBits}};
  desc.debugName = "math probe";
  Pipeline pipeline(device, desc);
  Buffer output(device,
                BufferDesc{count * sizeof(float),
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                           MemoryUsage::GpuOnly, "math probe output"});
  DescriptorArena arena(device, "math probe descriptors");
  if (timer != nullptr) timer->reset();
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    DescriptorWriter writer;
    writer.storageBuffer(0, output.vk());
    bindPipeline(device, cmd, pipeline, arena, writer);
    pushConstants(cmd, pipeline, count);
    const std::uint32_t scope = timer != nullptr ? timer->begin(cmd, "math probe") : 0;
    vkCmdDispatch(cmd, groupCount(count, 64), 1, 1);
    if (timer != nullptr) timer->end(cmd, scope);
  });
  const auto bytes = readbackBuffer(device, output);
  std::vector<float> values(count);
  std::memcpy(values.data(), bytes.data(), bytes.size());
  return values;
}

TEST_F(Compute, MathProbeMatchesCpuAndHonoursSpecialization) {
  constexpr std::uint32_t kCount = 10000;
  for (const float scale : {1.0f, -2.5f}) {
    const auto gpu = runMathProbe(device(), kCount, scale);
    for (std::uint32_t i = 0; i < kCount; ++i) {
      const float expected = cpuProbe(i, scale);
      ASSERT_NEAR(gpu[i], expected, 1e-4f * std::max(1.0f, std::abs(expected))) << "i=" << i;
    }
  }
}

TEST_F(Compute, StorageImagePatternReadsBackExactly) {
  const VkExtent2D extent{37, 23};  // not a multiple of the workgroup size
  ComputePipelineDesc desc;
  desc.spirv = image_pattern_comp_spv;
  desc.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_FORMAT_R8G8B8A8_UNORM}};
  desc.pushConstantBytes = 2 * sizeof(std::uint32_t);
  desc.debugName = "image pattern";
  Pipeline pipeline(device(), desc);
  Image image(device(), ImageDesc{VK_IMAGE_TYPE_2D,
                                  VK_FORMAT_R8G8B8A8_UNORM,
                                  {extent.width, extent.height, 1},
                                  1,
                                  1,
                                  VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  "pattern target"});
  DescriptorArena arena(device(), "pattern descriptors");
  device().immediateSubmit([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, image.vk(), image.fullRange(), kUndefined, kComputeGeneral);
    DescriptorWriter writer;
    writer.storageImage(0, image.view());
    bindPipeline(device(), cmd, pipeline, arena, writer);
    const std::uint32_t constants[2] = {extent.width, extent.height};
    vkCmdPushConstants(cmd, pipeline.layout(), pipeline.pushConstantStages(), 0, sizeof(constants),
                       constants);
    vkCmdDispatch(cmd, groupCount(extent.width, 8), groupCount(extent.height, 8), 1);
  });
  const auto bytes = readbackImage(device(), image, kComputeGeneral);
  ASSERT_EQ(bytes.size(), std::size_t{4} * extent.width * extent.height);
  for (std::uint32_t y = 0; y < extent.height; ++y) {
    for (std::uint32_t x = 0; x < extent.width; ++x) {
      const auto* p = reinterpret_cast<const std::uint8_t*>(&bytes[4 * (y * extent.width + x)]);
      ASSERT_EQ(p[0], x) << x << "," << y;
      ASSERT_EQ(p[1], y);
      ASSERT_EQ(p[2], (x ^ y) & 255u);
      ASSERT_EQ(p[3], 255);
    }
  }
}

TEST_F(Compute, TimestampsMeasureTheDispatch) {
  GpuTimer timer(device(), 4, "test timer");
  runMathProbe(device(), 1 << 20, 1.0f, &timer);
  const auto scopes = timer.resolve();
  ASSERT_EQ(scopes.size(), 1u);
  EXPECT_STREQ(scopes[0].name, "math probe");
  EXPECT_GT(scopes[0].milliseconds, 0.0);
  EXPECT_LT(scopes[0].milliseconds, 10000.0);
}

TEST_F(Compute, WarmUpRunsEveryPipelineValidationClean) {
  ComputePipelineDesc desc;
  desc.spirv = image_pattern_comp_spv;
  desc.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_FORMAT_R8G8B8A8_UNORM}};
  desc.pushConstantBytes = 2 * sizeof(std::uint32_t);
  desc.debugName = "warm-up probe";
  Pipeline a(device(), desc);
  ComputePipelineDesc probe;
  probe.spirv = math_probe_comp_spv;
  probe.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  probe.pushConstantBytes = sizeof(std::uint32_t);
  probe.debugName = "warm-up math probe";
  Pipeline b(device(), probe);
  const Pipeline* pipelines[] = {&a, &b};
  const double ms = warmUpPipelines(device(), pipelines);
  EXPECT_GE(ms, 0.0);
  // TearDown fails the test on any validation message from the stand-in resources.
}

}  // namespace
