// The memory allocator and deferred destruction on a real device.
#include <gtest/gtest.h>

#include "engine/gfx/resources.h"
#include "gpu_test.h"

namespace {

using namespace engine::gfx;

class Memory : public test::GpuTest {};

TEST_F(Memory, SmallResourcesShareBlocksAndLargeOnesGetTheirOwn) {
  device().waitIdle();
  const auto before = device().memory().stats();
  {
    std::vector<Buffer> buffers;
    for (int i = 0; i < 32; ++i) {
      buffers.emplace_back(device(), BufferDesc{4096, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                MemoryUsage::GpuOnly, "small buffer"});
    }
    const auto small = device().memory().stats();
    EXPECT_LE(small.blockCount, before.blockCount + 1) << "32 small buffers need one block";
    EXPECT_EQ(small.allocationCount, before.allocationCount + 32);

    Buffer large(device(), BufferDesc{MemoryAllocator::kDedicatedThresholdBytes + 4096,
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUsage::GpuOnly,
                                      "large buffer"});
    EXPECT_EQ(device().memory().stats().blockCount, small.blockCount + 1);
  }
  device().waitIdle();
  const auto after = device().memory().stats();
  EXPECT_EQ(after.allocationCount, before.allocationCount);
  EXPECT_EQ(after.usedBytes, before.usedBytes);
}

TEST_F(Memory, ReleaseWaitsForTheGpu) {
  device().waitIdle();
  const auto before = device().memory().stats().usedBytes;
  Buffer buffer(device(), BufferDesc{1 << 20, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                     MemoryUsage::GpuOnly, "released buffer"});
  buffer.reset();
  // The release is queued for the next submission; nothing has retired it yet.
  device().collectGarbage();
  EXPECT_GT(device().memory().stats().usedBytes, before);
  device().immediateSubmit([](VkCommandBuffer) {});
  EXPECT_EQ(device().memory().stats().usedBytes, before);
}

TEST_F(Memory, HostVisibleBuffersAreMappedAndGpuOnlyAreNot) {
  Buffer upload(device(), BufferDesc{256, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUsage::Upload,
                                     "upload buffer"});
  EXPECT_NE(upload.mapped(), nullptr);
  upload.mappedAs<float>()[3] = 1.5f;
  EXPECT_EQ(upload.mappedAs<float>()[3], 1.5f);
  Buffer readback(device(), BufferDesc{256, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback,
                                       "readback buffer"});
  EXPECT_NE(readback.mapped(), nullptr);
}

TEST_F(Memory, MovedFromResourcesReleaseNothing) {
  device().waitIdle();
  const auto before = device().memory().stats().allocationCount;
  Image a(device(), ImageDesc{VK_IMAGE_TYPE_3D,
                              VK_FORMAT_R8G8B8A8_UNORM,
                              {16, 16, 16},
                              1,
                              1,
                              VK_IMAGE_USAGE_SAMPLED_BIT,
                              "moved image"});
  Image b = std::move(a);
  EXPECT_FALSE(static_cast<bool>(a));
  EXPECT_TRUE(static_cast<bool>(b));
  b.reset();
  device().immediateSubmit([](VkCommandBuffer) {});
  EXPECT_EQ(device().memory().stats().allocationCount, before);
}

TEST_F(Memory, ExtraViewsOfOneMipAreValid) {
  Image image(device(), ImageDesc{VK_IMAGE_TYPE_2D,
                                  VK_FORMAT_R8G8B8A8_UNORM,
                                  {64, 64, 1},
                                  4,
                                  1,
                                  VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT,
                                  "mipped image"});
  std::vector<ImageView> mips;
  for (std::uint32_t mip = 0; mip < 4; ++mip) {
    mips.emplace_back(device(), image,
                      ImageViewDesc{VK_IMAGE_VIEW_TYPE_2D,
                                    VK_FORMAT_UNDEFINED,
                                    {VK_IMAGE_ASPECT_COLOR_BIT, mip, 1, 0, 1},
                                    "mip view"});
    EXPECT_NE(mips.back().vk(), VK_NULL_HANDLE);
  }
}

}  // namespace
