#pragma once
// A simple GPU memory sub-allocator (Debian has no VMA). Memory is taken from the driver in
// 64 MiB blocks per (memory type, linear-or-optimal) pair and handed out with
// BlockSuballocator; resources over 32 MiB get a dedicated block. Keeping buffers (linear) and
// optimal-tiling images in separate blocks sidesteps bufferImageGranularity. Host-visible
// blocks are always HOST_COHERENT and persistently mapped, so callers never flush.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "engine/gfx/block_suballocator.h"

namespace engine::gfx {

enum class MemoryUsage {
  GpuOnly,   // device-local; written by the GPU or through staging
  Upload,    // host-visible, coherent: CPU writes, GPU reads (staging, per-frame constants)
  Readback,  // host-visible, coherent, cached when available: GPU writes, CPU reads
};

enum class ResourceTiling { Linear, Optimal };

struct Allocation {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize size = 0;
  std::byte* mapped = nullptr;  // non-null for host-visible memory
  std::uint32_t blockIndex = 0;
  bool valid() const { return memory != VK_NULL_HANDLE; }
};

class MemoryAllocator {
 public:
  static constexpr VkDeviceSize kBlockBytes = VkDeviceSize{64} << 20;
  static constexpr VkDeviceSize kDedicatedThresholdBytes = VkDeviceSize{32} << 20;

  MemoryAllocator(VkPhysicalDevice physicalDevice, VkDevice device);
  ~MemoryAllocator();
  MemoryAllocator(const MemoryAllocator&) = delete;
  MemoryAllocator& operator=(const MemoryAllocator&) = delete;

  // Throws engine::Error naming `debugName` when no memory type fits or memory runs out.
  Allocation allocate(const VkMemoryRequirements& requirements, MemoryUsage usage,
                      ResourceTiling tiling, const char* debugName);
  void free(const Allocation& allocation);

  struct Stats {
    std::size_t blockCount = 0;
    VkDeviceSize reservedBytes = 0;  // taken from the driver
    VkDeviceSize usedBytes = 0;      // handed out to resources
    std::size_t allocationCount = 0;
  };
  Stats stats() const;

 private:
  struct Block {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    std::uint32_t memoryType = 0;
    ResourceTiling tiling = ResourceTiling::Linear;
    bool dedicated = false;
    std::byte* mapped = nullptr;
    std::unique_ptr<BlockSuballocator> ranges;
  };

  std::uint32_t chooseMemoryType(std::uint32_t typeBits, MemoryUsage usage,
                                 const char* debugName) const;
  std::uint32_t createBlock(std::uint32_t memoryType, ResourceTiling tiling, VkDeviceSize bytes,
                            bool dedicated, const char* debugName);
  void releaseBlock(std::uint32_t blockIndex);

  VkDevice device_;
  VkPhysicalDeviceMemoryProperties memoryProperties_{};
  mutable std::mutex mutex_;
  std::vector<Block> blocks_;  // released blocks stay as empty slots so indices remain stable
};

}  // namespace engine::gfx
