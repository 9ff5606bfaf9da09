// The memory allocator and deferred destruction on a real device.
#include <gtest/gtest.h>

#include <algorithm>
#include <span>

#include "engine/core/error.h"
#include "engine/gfx/resources.h"
#include "engine/gfx/upload.h"
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

// A mip chain goes up in one call, each level where it belongs (5x3, 2x1, 1x1: odd sides round
// down, none below 1), and comes back level by level; a wrong byte count or too many levels is
// refused naming the image.
TEST_F(Memory, AMipChainUploadsEachLevelInPlace) {
  Image image(device(), ImageDesc{VK_IMAGE_TYPE_2D,
                                  VK_FORMAT_R8G8B8A8_UNORM,
                                  {5, 3, 1},
                                  3,
                                  1,
                                  VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  "mip chain"});
  const std::size_t texels[3] = {5 * 3, 2 * 1, 1};
  std::vector<std::byte> bytes;
  for (std::size_t level = 0; level < 3; ++level) {
    for (std::size_t i = 0; i < 4 * texels[level]; ++i) {
      bytes.push_back(std::byte(16 * (level + 1) + i % 16));
    }
  }
  const ImageState sampled{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                           VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
  uploadMipsToImage(device(), image, bytes, 3, sampled);
  std::size_t offset = 0;
  for (std::uint32_t level = 0; level < 3; ++level) {
    const std::vector<std::byte> back = readbackImage(device(), image, sampled, level);
    ASSERT_EQ(back.size(), 4 * texels[level]) << "mip " << level;
    EXPECT_TRUE(std::equal(back.begin(), back.end(), bytes.begin() + std::ptrdiff_t(offset)))
        << "mip " << level;
    offset += back.size();
  }
  EXPECT_THROW(
      uploadMipsToImage(device(), image, std::span(bytes).first(bytes.size() - 4), 3, sampled),
      engine::Error);
  EXPECT_THROW(uploadMipsToImage(device(), image, bytes, 4, sampled), engine::Error);
}

}  // namespace
