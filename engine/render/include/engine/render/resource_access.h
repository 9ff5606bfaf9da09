#pragma once
// How a pass uses a resource, and the Vulkan state (layout, stages, access) each use needs.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace engine::render {

// The kind of work a pass records; it decides the pipeline stages of shader accesses.
enum class PassType : std::uint8_t { Compute, Graphics, Transfer };

enum class Access : std::uint8_t {
  // textures
  SampledRead,         // texture()/texelFetch() in a shader (SHADER_READ_ONLY, or depth read-only)
  SampledReadGeneral,  // texture() of an image kept in GENERAL (a module's output it rewrites)
  StorageRead,         // imageLoad() (GENERAL)
  StorageWrite,        // imageStore(), possibly with imageLoad() of the same texels (GENERAL)
  ColorAttachment,     // colour target of a graphics pass
  DepthAttachment,     // depth target of a graphics pass, tested and written
  DepthReadOnlyAttachment,  // depth target tested but not written
  TransferSrc,
  TransferDst,
  // buffers
  UniformRead,
  StorageBufferRead,
  StorageBufferWrite,
  VertexRead,
  IndexRead,
};

bool isWrite(Access access);
bool isTextureAccess(Access access);

struct ResourceState {
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // ignored for buffers
  VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

// The state `access` needs in a pass of `type`. `depthFormat` picks depth layouts for sampling.
ResourceState stateFor(Access access, PassType type, bool depthFormat);
// The usage flags a texture or buffer needs for `access`.
VkImageUsageFlags imageUsageFor(Access access);
VkBufferUsageFlags bufferUsageFor(Access access);

const char* accessName(Access access);

}  // namespace engine::render
