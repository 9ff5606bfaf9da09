#include <gtest/gtest.h>

#include <map>
#include <random>

#include "engine/core/error.h"
#include "engine/gfx/block_suballocator.h"

namespace {

using engine::gfx::BlockSuballocator;

TEST(BlockSuballocator, AlignsAndFillsFromTheFront) {
  BlockSuballocator block(1024);
  const auto a = block.allocate(100, 1);
  const auto b = block.allocate(10, 256);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->offset, 0u);
  EXPECT_EQ(b->offset, 256u);
  EXPECT_EQ(block.usedBytes(), 110u);
  // The padding between 100 and 256 stays usable.
  const auto c = block.allocate(100, 4);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->offset, 100u);
}

TEST(BlockSuballocator, RejectsWhatDoesNotFitAndBadArguments) {
  BlockSuballocator block(256);
  EXPECT_FALSE(block.allocate(257, 1));
  EXPECT_FALSE(block.allocate(0, 1));
  EXPECT_FALSE(block.allocate(16, 3));  // alignment must be a power of two
  ASSERT_TRUE(block.allocate(256, 1));
  EXPECT_FALSE(block.allocate(1, 1));
}

TEST(BlockSuballocator, FreeCoalescesNeighbours) {
  BlockSuballocator block(300);
  const auto a = block.allocate(100, 1);
  const auto b = block.allocate(100, 1);
  const auto c = block.allocate(100, 1);
  ASSERT_TRUE(a && b && c);
  block.free(a->offset);
  block.free(c->offset);
  EXPECT_EQ(block.freeRangeCount(), 2u);
  block.free(b->offset);
  EXPECT_EQ(block.freeRangeCount(), 1u);
  EXPECT_TRUE(block.empty());
  EXPECT_TRUE(block.allocate(300, 1));  // the whole block is one range again
}

TEST(BlockSuballocator, FreeOfUnknownOffsetThrows) {
  BlockSuballocator block(64);
  EXPECT_THROW(block.free(8), engine::Error);
}

// Random allocations and frees against a model: no two live ranges overlap, every range is
// aligned and inside the block, and freeing everything restores one free range.
TEST(BlockSuballocator, RandomisedAgainstOverlapModel) {
  constexpr std::uint64_t kCapacity = 1 << 16;
  BlockSuballocator block(kCapacity);
  std::mt19937 rng(1234);
  std::map<std::uint64_t, std::uint64_t> live;  // offset -> size
  for (int step = 0; step < 20000; ++step) {
    const bool doAllocate = live.empty() || (rng() % 100) < 55;
    if (doAllocate) {
      const std::uint64_t size = 1 + rng() % 700;
      const std::uint64_t alignment = std::uint64_t{1} << (rng() % 9);
      const auto range = block.allocate(size, alignment);
      if (!range) continue;
      ASSERT_EQ(range->offset % alignment, 0u);
      ASSERT_LE(range->offset + size, kCapacity);
      auto next = live.lower_bound(range->offset);
      if (next != live.end()) {
        ASSERT_LE(range->offset + size, next->first);
      }
      if (next != live.begin()) {
        auto prev = std::prev(next);
        ASSERT_LE(prev->first + prev->second, range->offset);
      }
      live.emplace(range->offset, size);
    } else {
      auto it = live.begin();
      std::advance(it, static_cast<long>(rng() % live.size()));
      block.free(it->first);
      live.erase(it);
    }
  }
  std::uint64_t used = 0;
  for (const auto& [offset, size] : live) used += size;
  EXPECT_EQ(block.usedBytes(), used);
  for (const auto& [offset, size] : live) block.free(offset);
  EXPECT_EQ(block.freeRangeCount(), 1u);
  EXPECT_EQ(block.usedBytes(), 0u);
}

}  // namespace
