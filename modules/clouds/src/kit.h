#pragma once
// The Vulkan effect kit (modules/vkfx) under the names the module's internals use: the function
// table, RAII owners, the device context, images and buffers, compute programs and the pass
// timer are shared with the project's other effect modules.
#include "vkfx/compute_program.h"
#include "vkfx/device_context.h"
#include "vkfx/owned_resources.h"
#include "vkfx/pass_timer.h"
#include "vkfx/vk_handle.h"
#include "vkfx/vulkan_functions.h"

namespace clouds::detail {

using vkfx::barrier;
using vkfx::Binding;
using vkfx::bits;
using vkfx::check;
using vkfx::ComputeProgram;
using vkfx::DeviceContext;
using vkfx::groupsFor;
using vkfx::kComputeStage;
using vkfx::kStorageRead;
using vkfx::kStorageWrite;
using vkfx::memoryBarrier;
using vkfx::OwnedBuffer;
using vkfx::OwnedImage;
using vkfx::PassTimer;
using vkfx::SetWriter;
using vkfx::SpecializationKey;
using vkfx::UniqueDescriptorPool;
using vkfx::UniqueSampler;
using vkfx::VulkanFunctions;

// Where and how host passes may read the module's outputs (compute and fragment shaders, as
// storage images or sampled): the stages and accesses the output barriers make them visible to.
inline constexpr VkPipelineStageFlags2 kHostReadStages =
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
inline constexpr VkAccessFlags2 kHostReadAccess =
    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;

}  // namespace clouds::detail
