#pragma once
// The Vulkan effect kit (modules/vkfx) under the names the module's internals use.
#include "vkfx/compute_program.h"
#include "vkfx/device_context.h"
#include "vkfx/owned_resources.h"
#include "vkfx/pass_timer.h"
#include "vkfx/vk_handle.h"
#include "vkfx/vulkan_functions.h"

namespace atmosphere::detail {

using vkfx::barrier;
using vkfx::Binding;
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

}  // namespace atmosphere::detail
