#include "vkfx/device_context.h"

namespace vkfx {

void check(VkResult result, const char* what) {
  if (result == VK_SUCCESS) return;
  // Host, device and descriptor-pool memory alike: the host can only free some and retry.
  const bool outOfMemory =
      result == VK_ERROR_OUT_OF_HOST_MEMORY || result == VK_ERROR_OUT_OF_DEVICE_MEMORY ||
      result == VK_ERROR_OUT_OF_POOL_MEMORY || result == VK_ERROR_FRAGMENTED_POOL;
  throw Error(
      outOfMemory ? Failure::OutOfMemory : Failure::VulkanFailure,
      std::string(what) + " failed (VkResult " + std::to_string(static_cast<int>(result)) + ")");
}

DeviceContext::DeviceContext(VkDevice device, VkPhysicalDevice physical, bool debugUtils,
                             const VulkanFunctions& functions, std::string prefix)
    : fn_(functions),
      device_(device),
      physical_(physical),
      debugUtils_(debugUtils),
      prefix_(std::move(prefix)) {
  fn_.vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
}

std::uint32_t DeviceContext::memoryType(std::uint32_t typeBits,
                                        VkMemoryPropertyFlags wanted) const {
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & wanted) == wanted) {
      return i;
    }
  }
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if (typeBits & (1u << i)) return i;  // no preferred type: any that fits
  }
  throw Error(Failure::Unsupported, prefix_ + ": no memory type fits a module resource");
}

bool DeviceContext::supportsStorage(VkFormat format) const {
  VkFormatProperties properties{};
  fn_.vkGetPhysicalDeviceFormatProperties(physical_, format, &properties);
  return (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT) != 0;
}

void DeviceContext::name(VkObjectType type, std::uint64_t handle, const std::string& name) const {
  if (!debugUtils_ || fn_.vkSetDebugUtilsObjectNameEXT == nullptr || handle == 0) return;
  const std::string full = prefix_ + ": " + name;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = full.c_str();
  fn_.vkSetDebugUtilsObjectNameEXT(device_, &info);
}

void DeviceContext::beginLabel(VkCommandBuffer cmd, const char* name) const {
  if (!debugUtils_ || fn_.vkCmdBeginDebugUtilsLabelEXT == nullptr) return;
  VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  label.pLabelName = name;
  fn_.vkCmdBeginDebugUtilsLabelEXT(cmd, &label);
}

void DeviceContext::endLabel(VkCommandBuffer cmd) const {
  if (debugUtils_ && fn_.vkCmdEndDebugUtilsLabelEXT != nullptr) {
    fn_.vkCmdEndDebugUtilsLabelEXT(cmd);
  }
}

// Each creation: call, check, wrap, name. The wrap comes before anything else can throw.
template <typename Unique, auto Create, typename Info>
Unique DeviceContext::make(const Info& info, VkObjectType type, const char* what,
                           const std::string& name) const {
  typename Unique::Handle handle{};
  check((fn_.*Create)(device_, &info, nullptr, &handle), what);
  Unique owned(fn_, device_, handle);
  this->name(type, bits(handle), name);
  return owned;
}

UniqueImage DeviceContext::createImage(const VkImageCreateInfo& info,
                                       const std::string& name) const {
  return make<UniqueImage, &VulkanFunctions::vkCreateImage>(info, VK_OBJECT_TYPE_IMAGE,
                                                            "vkCreateImage", name);
}

UniqueImageView DeviceContext::createImageView(const VkImageViewCreateInfo& info,
                                               const std::string& name) const {
  return make<UniqueImageView, &VulkanFunctions::vkCreateImageView>(info, VK_OBJECT_TYPE_IMAGE_VIEW,
                                                                    "vkCreateImageView", name);
}

UniqueBuffer DeviceContext::createBuffer(const VkBufferCreateInfo& info,
                                         const std::string& name) const {
  return make<UniqueBuffer, &VulkanFunctions::vkCreateBuffer>(info, VK_OBJECT_TYPE_BUFFER,
                                                              "vkCreateBuffer", name);
}

UniqueMemory DeviceContext::allocateMemory(const VkMemoryAllocateInfo& info,
                                           const std::string& name) const {
  return make<UniqueMemory, &VulkanFunctions::vkAllocateMemory>(info, VK_OBJECT_TYPE_DEVICE_MEMORY,
                                                                "vkAllocateMemory", name);
}

UniqueMemory DeviceContext::allocateFor(const VkMemoryRequirements& requirements,
                                        VkMemoryPropertyFlags preferred,
                                        const std::string& name) const {
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = requirements.size;
  info.memoryTypeIndex = memoryType(requirements.memoryTypeBits, preferred);
  return allocateMemory(info, name + " memory");
}

UniqueSampler DeviceContext::createSampler(const VkSamplerCreateInfo& info,
                                           const std::string& name) const {
  return make<UniqueSampler, &VulkanFunctions::vkCreateSampler>(info, VK_OBJECT_TYPE_SAMPLER,
                                                                "vkCreateSampler", name);
}

UniqueSampler DeviceContext::createSampler(VkFilter filter, VkSamplerAddressMode addressU,
                                           const std::string& name) const {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = addressU;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  return createSampler(info, name);
}

UniqueShaderModule DeviceContext::createShaderModule(const VkShaderModuleCreateInfo& info,
                                                     const std::string& name) const {
  return make<UniqueShaderModule, &VulkanFunctions::vkCreateShaderModule>(
      info, VK_OBJECT_TYPE_SHADER_MODULE, "vkCreateShaderModule", name);
}

UniqueSetLayout DeviceContext::createSetLayout(const VkDescriptorSetLayoutCreateInfo& info,
                                               const std::string& name) const {
  return make<UniqueSetLayout, &VulkanFunctions::vkCreateDescriptorSetLayout>(
      info, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, "vkCreateDescriptorSetLayout", name);
}

UniquePipelineLayout DeviceContext::createPipelineLayout(const VkPipelineLayoutCreateInfo& info,
                                                         const std::string& name) const {
  return make<UniquePipelineLayout, &VulkanFunctions::vkCreatePipelineLayout>(
      info, VK_OBJECT_TYPE_PIPELINE_LAYOUT, "vkCreatePipelineLayout", name);
}

UniqueDescriptorPool DeviceContext::createDescriptorPool(const VkDescriptorPoolCreateInfo& info,
                                                         const std::string& name) const {
  return make<UniqueDescriptorPool, &VulkanFunctions::vkCreateDescriptorPool>(
      info, VK_OBJECT_TYPE_DESCRIPTOR_POOL, "vkCreateDescriptorPool", name);
}

UniqueQueryPool DeviceContext::createQueryPool(const VkQueryPoolCreateInfo& info,
                                               const std::string& name) const {
  return make<UniqueQueryPool, &VulkanFunctions::vkCreateQueryPool>(info, VK_OBJECT_TYPE_QUERY_POOL,
                                                                    "vkCreateQueryPool", name);
}

template <auto Create, typename Info>
UniquePipeline DeviceContext::makePipeline(const Info& info, const char* what,
                                           const std::string& name) const {
  VkPipeline handle = VK_NULL_HANDLE;
  check((fn_.*Create)(device_, VK_NULL_HANDLE, 1, &info, nullptr, &handle), what);
  UniquePipeline owned(fn_, device_, handle);
  this->name(VK_OBJECT_TYPE_PIPELINE, bits(handle), name);
  return owned;
}

UniquePipeline DeviceContext::createGraphicsPipeline(const VkGraphicsPipelineCreateInfo& info,
                                                     const std::string& name) const {
  return makePipeline<&VulkanFunctions::vkCreateGraphicsPipelines>(
      info, "vkCreateGraphicsPipelines", name);
}

UniquePipeline DeviceContext::createComputePipeline(const VkComputePipelineCreateInfo& info,
                                                    const std::string& name) const {
  return makePipeline<&VulkanFunctions::vkCreateComputePipelines>(info, "vkCreateComputePipelines",
                                                                  name);
}

void barrier(const DeviceContext& context, VkCommandBuffer cmd, VkImage image,
             VkImageLayout oldLayout, VkImageLayout newLayout, VkPipelineStageFlags2 srcStages,
             VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = srcStages;
  b.srcAccessMask = srcAccess;
  b.dstStageMask = dstStages;
  b.dstAccessMask = dstAccess;
  b.oldLayout = oldLayout;
  b.newLayout = newLayout;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &b;
  context.fn().vkCmdPipelineBarrier2(cmd, &dependency);
}

void memoryBarrier(const DeviceContext& context, VkCommandBuffer cmd,
                   VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
  VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  b.srcStageMask = srcStages;
  b.srcAccessMask = srcAccess;
  b.dstStageMask = dstStages;
  b.dstAccessMask = dstAccess;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.memoryBarrierCount = 1;
  dependency.pMemoryBarriers = &b;
  context.fn().vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace vkfx
