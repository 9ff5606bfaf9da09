#include "engine/gfx/memory_allocator.h"

#include <string>

#include "engine/core/error.h"
#include "engine/gfx/vk_check.h"

namespace engine::gfx {
namespace {

VkMemoryPropertyFlags requiredFlags(MemoryUsage usage) {
  switch (usage) {
    case MemoryUsage::GpuOnly:
      return 0;
    case MemoryUsage::Upload:
    case MemoryUsage::Readback:
      return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  }
  return 0;
}

VkMemoryPropertyFlags preferredFlags(MemoryUsage usage) {
  switch (usage) {
    case MemoryUsage::GpuOnly:
      return VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    case MemoryUsage::Upload:
      return 0;
    case MemoryUsage::Readback:
      return VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
  }
  return 0;
}

}  // namespace

MemoryAllocator::MemoryAllocator(VkPhysicalDevice physicalDevice, VkDevice device)
    : device_(device) {
  vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties_);
}

MemoryAllocator::~MemoryAllocator() {
  for (std::uint32_t i = 0; i < blocks_.size(); ++i) releaseBlock(i);
}

std::uint32_t MemoryAllocator::chooseMemoryType(std::uint32_t typeBits, MemoryUsage usage,
                                                const char* debugName) const {
  const VkMemoryPropertyFlags required = requiredFlags(usage);
  const VkMemoryPropertyFlags preferred = preferredFlags(usage);
  std::uint32_t best = UINT32_MAX;
  for (std::uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) == 0) continue;
    const VkMemoryPropertyFlags flags = memoryProperties_.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (best == UINT32_MAX) best = i;
  }
  if (best == UINT32_MAX) {
    throw Error(std::string("GPU memory for '") + debugName +
                "': no memory type satisfies the resource's requirements");
  }
  return best;
}

std::uint32_t MemoryAllocator::createBlock(std::uint32_t memoryType, ResourceTiling tiling,
                                           VkDeviceSize bytes, bool dedicated,
                                           const char* debugName) {
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = bytes;
  info.memoryTypeIndex = memoryType;
  Block block;
  const VkResult result = vkAllocateMemory(device_, &info, nullptr, &block.memory);
  if (result != VK_SUCCESS) {
    throw Error(std::string("GPU memory for '") + debugName + "': vkAllocateMemory of " +
                std::to_string(bytes) + " bytes failed with " + resultName(result));
  }
  block.memoryType = memoryType;
  block.tiling = tiling;
  block.dedicated = dedicated;
  block.ranges = std::make_unique<BlockSuballocator>(bytes);
  const VkMemoryPropertyFlags flags = memoryProperties_.memoryTypes[memoryType].propertyFlags;
  if (flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
    void* mapped = nullptr;
    GFX_CHECK(vkMapMemory(device_, block.memory, 0, VK_WHOLE_SIZE, 0, &mapped));
    block.mapped = static_cast<std::byte*>(mapped);
  }
  for (std::uint32_t i = 0; i < blocks_.size(); ++i) {
    if (blocks_[i].memory == VK_NULL_HANDLE) {
      blocks_[i] = std::move(block);
      return i;
    }
  }
  blocks_.push_back(std::move(block));
  return static_cast<std::uint32_t>(blocks_.size() - 1);
}

void MemoryAllocator::releaseBlock(std::uint32_t blockIndex) {
  Block& block = blocks_[blockIndex];
  if (block.memory == VK_NULL_HANDLE) return;
  if (block.mapped != nullptr) vkUnmapMemory(device_, block.memory);
  vkFreeMemory(device_, block.memory, nullptr);
  block = Block{};
}

Allocation MemoryAllocator::allocate(const VkMemoryRequirements& requirements, MemoryUsage usage,
                                     ResourceTiling tiling, const char* debugName) {
  std::lock_guard lock(mutex_);
  const std::uint32_t memoryType = chooseMemoryType(requirements.memoryTypeBits, usage, debugName);
  const VkDeviceSize alignment = requirements.alignment == 0 ? 1 : requirements.alignment;

  auto take = [&](std::uint32_t blockIndex) -> std::optional<Allocation> {
    Block& block = blocks_[blockIndex];
    const auto range = block.ranges->allocate(requirements.size, alignment);
    if (!range) return std::nullopt;
    Allocation allocation;
    allocation.memory = block.memory;
    allocation.offset = range->offset;
    allocation.size = range->size;
    allocation.mapped = block.mapped != nullptr ? block.mapped + range->offset : nullptr;
    allocation.blockIndex = blockIndex;
    return allocation;
  };

  if (requirements.size > kDedicatedThresholdBytes) {
    const std::uint32_t index =
        createBlock(memoryType, tiling, requirements.size, /*dedicated=*/true, debugName);
    return *take(index);
  }
  for (std::uint32_t i = 0; i < blocks_.size(); ++i) {
    const Block& block = blocks_[i];
    if (block.memory == VK_NULL_HANDLE || block.dedicated || block.memoryType != memoryType ||
        block.tiling != tiling) {
      continue;
    }
    if (auto allocation = take(i)) return *allocation;
  }
  const std::uint32_t index =
      createBlock(memoryType, tiling, kBlockBytes, /*dedicated=*/false, debugName);
  auto allocation = take(index);
  if (!allocation) {
    throw Error(std::string("GPU memory for '") + debugName + "': a fresh block cannot hold " +
                std::to_string(requirements.size) + " bytes");
  }
  return *allocation;
}

void MemoryAllocator::free(const Allocation& allocation) {
  if (!allocation.valid()) return;
  std::lock_guard lock(mutex_);
  Block& block = blocks_.at(allocation.blockIndex);
  block.ranges->free(allocation.offset);
  // Dedicated blocks go back at once; shared blocks stay for reuse (frees happen at load/resize,
  // so holding a few empty 64 MiB blocks is cheaper than churning the driver).
  if (block.dedicated) releaseBlock(allocation.blockIndex);
}

MemoryAllocator::Stats MemoryAllocator::stats() const {
  std::lock_guard lock(mutex_);
  Stats stats;
  for (const Block& block : blocks_) {
    if (block.memory == VK_NULL_HANDLE) continue;
    ++stats.blockCount;
    stats.reservedBytes += block.ranges->capacity();
    stats.usedBytes += block.ranges->usedBytes();
    stats.allocationCount += block.ranges->allocationCount();
  }
  return stats;
}

}  // namespace engine::gfx
