#pragma once
// Deferred destruction: an object released while the GPU may still use it is queued with the
// timeline value of the next submission and destroyed once the GPU has passed that value.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "engine/gfx/memory_allocator.h"

namespace engine::gfx {

class DeferredReleaseQueue {
 public:
  void push(VkObjectType type, std::uint64_t handle, const Allocation& allocation,
            std::uint64_t retireValue);
  // Destroys every entry whose retire value is <= completedValue.
  void collect(std::uint64_t completedValue, VkDevice device, MemoryAllocator& memory);
  std::size_t pending() const { return entries_.size(); }

 private:
  struct Entry {
    VkObjectType type;
    std::uint64_t handle;
    Allocation allocation;
    std::uint64_t retireValue;
  };
  static void destroy(const Entry& entry, VkDevice device, MemoryAllocator& memory);

  std::vector<Entry> entries_;
};

}  // namespace engine::gfx
