#pragma once
// Load-time transfers through staging buffers: uploads into GPU-only buffers and images, and
// readback of images (tests, captures outside the frame graph). Each call submits and waits.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/gfx/barriers.h"
#include "engine/gfx/device.h"
#include "engine/gfx/resources.h"

namespace engine::gfx {

void uploadToBuffer(Device& device, const Buffer& destination, std::span<const std::byte> data,
                    VkDeviceSize destinationOffset = 0);

// Uploads mip 0 / layer 0 of `destination` (tightly packed texels) and leaves the image in
// `finalState`.
void uploadToImage(Device& device, const Image& destination, std::span<const std::byte> texels,
                   const ImageState& finalState);
// Uploads mips 0 to `levels` - 1 of layer 0: `texels` holds each in turn, tightly packed (a
// mip's sides are its image's halved per level, at least 1).
void uploadMipsToImage(Device& device, const Image& destination, std::span<const std::byte> texels,
                       std::uint32_t levels, const ImageState& finalState);

// Copies mip `level` / layer 0 of `source` (currently in `currentState`) back to the host,
// tightly packed, and returns the image to `currentState`.
std::vector<std::byte> readbackImage(Device& device, const Image& source,
                                     const ImageState& currentState, std::uint32_t level = 0);
// The same for an image another component owns (a module's output): colour aspect, one layer.
std::vector<std::byte> readbackImage(Device& device, VkImage source, VkFormat format,
                                     VkExtent3D extent, const ImageState& currentState);

std::vector<std::byte> readbackBuffer(Device& device, const Buffer& source);

}  // namespace engine::gfx
