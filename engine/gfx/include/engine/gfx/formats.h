#pragma once
// Format facts the engine needs: aspect masks and texel sizes.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace engine::gfx {

bool isDepthFormat(VkFormat format);
bool hasStencil(VkFormat format);
VkImageAspectFlags aspectMask(VkFormat format);
// Bytes per texel for the uncompressed formats the engine uses; throws for others.
std::uint32_t texelBytes(VkFormat format);

}  // namespace engine::gfx
