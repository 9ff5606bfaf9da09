#pragma once
// Offset bookkeeping inside one memory block: first-fit over a free list ordered by offset,
// with alignment and coalescing of neighbours on free. Pure logic (no Vulkan), unit-tested.
#include <cstdint>
#include <map>
#include <optional>

namespace engine::gfx {

class BlockSuballocator {
 public:
  explicit BlockSuballocator(std::uint64_t capacityBytes);

  struct Range {
    std::uint64_t offset = 0;
    std::uint64_t size = 0;
  };

  // Returns the aligned range, or nullopt when no free range fits. `alignment` must be a power
  // of two. Sizes of 0 are rejected (nullopt).
  std::optional<Range> allocate(std::uint64_t size, std::uint64_t alignment);
  // Frees a range returned by allocate(). Freeing an unknown range throws engine::Error.
  void free(std::uint64_t offset);

  std::uint64_t capacity() const { return capacity_; }
  std::uint64_t usedBytes() const { return used_; }
  std::size_t freeRangeCount() const { return freeRanges_.size(); }
  std::size_t allocationCount() const { return allocations_.size(); }
  bool empty() const { return allocations_.empty(); }

 private:
  std::uint64_t capacity_;
  std::uint64_t used_ = 0;
  std::map<std::uint64_t, std::uint64_t> freeRanges_;  // offset -> size
  // offset handed out -> {start of the consumed span (before alignment padding), span size}
  std::map<std::uint64_t, Range> allocations_;
};

}  // namespace engine::gfx
