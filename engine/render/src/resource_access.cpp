#include "engine/render/resource_access.h"

namespace engine::render {
namespace {

VkPipelineStageFlags2 shaderStages(PassType type) {
  switch (type) {
    case PassType::Compute:
      return VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    case PassType::Graphics:
      return VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    case PassType::Transfer:
      return VK_PIPELINE_STAGE_2_TRANSFER_BIT;
  }
  return VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
}

constexpr VkPipelineStageFlags2 kDepthStages =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

}  // namespace

bool isWrite(Access access) {
  switch (access) {
    case Access::StorageWrite:
    case Access::ColorAttachment:
    case Access::DepthAttachment:
    case Access::TransferDst:
    case Access::StorageBufferWrite:
      return true;
    default:
      return false;
  }
}

bool isTextureAccess(Access access) {
  switch (access) {
    case Access::UniformRead:
    case Access::StorageBufferRead:
    case Access::StorageBufferWrite:
    case Access::VertexRead:
    case Access::IndexRead:
      return false;
    case Access::TransferSrc:
    case Access::TransferDst:
      return true;  // also valid on buffers; see stateFor
    default:
      return true;
  }
}

ResourceState stateFor(Access access, PassType type, bool depthFormat) {
  switch (access) {
    case Access::SampledRead:
      return {depthFormat ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                          : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
              shaderStages(type), VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
    case Access::SampledReadGeneral:
      return {VK_IMAGE_LAYOUT_GENERAL, shaderStages(type), VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
    case Access::StorageRead:
      return {VK_IMAGE_LAYOUT_GENERAL, shaderStages(type), VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
    case Access::StorageWrite:
      return {VK_IMAGE_LAYOUT_GENERAL, shaderStages(type),
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    case Access::ColorAttachment:
      return {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
              VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
    case Access::DepthAttachment:
      return {VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, kDepthStages,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                  VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
    case Access::DepthReadOnlyAttachment:
      return {VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, kDepthStages,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT};
    case Access::TransferSrc:
      return {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
              VK_ACCESS_2_TRANSFER_READ_BIT};
    case Access::TransferDst:
      return {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
              VK_ACCESS_2_TRANSFER_WRITE_BIT};
    case Access::UniformRead:
      return {VK_IMAGE_LAYOUT_UNDEFINED, shaderStages(type), VK_ACCESS_2_UNIFORM_READ_BIT};
    case Access::StorageBufferRead:
      return {VK_IMAGE_LAYOUT_UNDEFINED, shaderStages(type), VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
    case Access::StorageBufferWrite:
      return {VK_IMAGE_LAYOUT_UNDEFINED, shaderStages(type),
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    case Access::VertexRead:
      return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
              VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT};
    case Access::IndexRead:
      return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT,
              VK_ACCESS_2_INDEX_READ_BIT};
  }
  return {};
}

VkImageUsageFlags imageUsageFor(Access access) {
  switch (access) {
    case Access::SampledRead:
    case Access::SampledReadGeneral:
      return VK_IMAGE_USAGE_SAMPLED_BIT;
    case Access::StorageRead:
    case Access::StorageWrite:
      return VK_IMAGE_USAGE_STORAGE_BIT;
    case Access::ColorAttachment:
      return VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    case Access::DepthAttachment:
    case Access::DepthReadOnlyAttachment:
      return VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    case Access::TransferSrc:
      return VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    case Access::TransferDst:
      return VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    default:
      return 0;
  }
}

VkBufferUsageFlags bufferUsageFor(Access access) {
  switch (access) {
    case Access::UniformRead:
      return VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    case Access::StorageBufferRead:
    case Access::StorageBufferWrite:
      return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    case Access::VertexRead:
      return VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    case Access::IndexRead:
      return VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
    case Access::TransferSrc:
      return VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    case Access::TransferDst:
      return VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    default:
      return 0;
  }
}

const char* accessName(Access access) {
  switch (access) {
    case Access::SampledRead:
      return "SampledRead";
    case Access::SampledReadGeneral:
      return "SampledReadGeneral";
    case Access::StorageRead:
      return "StorageRead";
    case Access::StorageWrite:
      return "StorageWrite";
    case Access::ColorAttachment:
      return "ColorAttachment";
    case Access::DepthAttachment:
      return "DepthAttachment";
    case Access::DepthReadOnlyAttachment:
      return "DepthReadOnlyAttachment";
    case Access::TransferSrc:
      return "TransferSrc";
    case Access::TransferDst:
      return "TransferDst";
    case Access::UniformRead:
      return "UniformRead";
    case Access::StorageBufferRead:
      return "StorageBufferRead";
    case Access::StorageBufferWrite:
      return "StorageBufferWrite";
    case Access::VertexRead:
      return "VertexRead";
    case Access::IndexRead:
      return "IndexRead";
  }
  return "?";
}

}  // namespace engine::render
