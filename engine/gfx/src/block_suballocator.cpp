#include "engine/gfx/block_suballocator.h"

#include "engine/core/error.h"

namespace engine::gfx {

BlockSuballocator::BlockSuballocator(std::uint64_t capacityBytes) : capacity_(capacityBytes) {
  if (capacityBytes > 0) freeRanges_.emplace(0, capacityBytes);
}

std::optional<BlockSuballocator::Range> BlockSuballocator::allocate(std::uint64_t size,
                                                                    std::uint64_t alignment) {
  if (size == 0 || alignment == 0 || (alignment & (alignment - 1)) != 0) return std::nullopt;
  for (auto it = freeRanges_.begin(); it != freeRanges_.end(); ++it) {
    const std::uint64_t start = it->first;
    const std::uint64_t length = it->second;
    const std::uint64_t aligned = (start + alignment - 1) & ~(alignment - 1);
    const std::uint64_t padding = aligned - start;
    if (padding > length || length - padding < size) continue;

    // The padding before `aligned` stays free; the tail after the allocation stays free.
    const std::uint64_t tailOffset = aligned + size;
    const std::uint64_t tailSize = start + length - tailOffset;
    freeRanges_.erase(it);
    if (padding > 0) freeRanges_.emplace(start, padding);
    if (tailSize > 0) freeRanges_.emplace(tailOffset, tailSize);
    allocations_.emplace(aligned, Range{aligned, size});
    used_ += size;
    return Range{aligned, size};
  }
  return std::nullopt;
}

void BlockSuballocator::free(std::uint64_t offset) {
  const auto found = allocations_.find(offset);
  if (found == allocations_.end()) {
    throw Error("BlockSuballocator::free: no allocation at offset " + std::to_string(offset));
  }
  std::uint64_t start = found->second.offset;
  std::uint64_t size = found->second.size;
  used_ -= size;
  allocations_.erase(found);

  // Coalesce with the following free range, then with the preceding one.
  auto next = freeRanges_.lower_bound(start);
  if (next != freeRanges_.end() && next->first == start + size) {
    size += next->second;
    next = freeRanges_.erase(next);
  }
  if (next != freeRanges_.begin()) {
    auto prev = std::prev(next);
    if (prev->first + prev->second == start) {
      start = prev->first;
      size += prev->second;
      freeRanges_.erase(prev);
    }
  }
  freeRanges_.emplace(start, size);
}

}  // namespace engine::gfx
