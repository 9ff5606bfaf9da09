#include "engine/gfx/device.h"

#include <cstring>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/gfx/device_selection.h"
#include "engine/gfx/vk_check.h"

namespace engine::gfx {
namespace {

bool hasExtension(VkPhysicalDevice physical, const char* name) {
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, extensions.data());
  for (const auto& e : extensions) {
    if (std::strcmp(e.extensionName, name) == 0) return true;
  }
  return false;
}

struct FeatureChain {
  VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  FeatureChain() {
    core.pNext = &v12;
    v12.pNext = &v13;
  }
  FeatureChain(const FeatureChain&) = delete;
};

// The features the engine and the effect modules it hosts rely on; missing ones make a device
// unsuitable.
std::string missingRequiredFeature(const FeatureChain& f) {
  if (!f.v12.timelineSemaphore) return "timelineSemaphore";
  if (!f.v12.hostQueryReset) return "hostQueryReset";
  if (!f.v13.dynamicRendering) return "dynamicRendering";
  if (!f.v13.synchronization2) return "synchronization2";
  if (!f.v13.maintenance4) return "maintenance4";
  if (!f.core.features.shaderStorageImageExtendedFormats) {
    return "shaderStorageImageExtendedFormats";
  }
  return {};
}

std::optional<std::uint32_t> findQueueFamily(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if ((families[i].queueFlags & needed) != needed) continue;
    if (families[i].timestampValidBits == 0) continue;
    if (surface != VK_NULL_HANDLE) {
      VkBool32 present = VK_FALSE;
      vkGetPhysicalDeviceSurfaceSupportKHR(physical, i, surface, &present);
      if (!present) continue;
    }
    return i;
  }
  return std::nullopt;
}

}  // namespace

Device::Device(Instance& instance, const DeviceDesc& desc) : instance_(instance) {
  pickPhysicalDevice(desc);
  try {
    createLogicalDevice();
    memory_ = std::make_unique<MemoryAllocator>(physical_, device_);
  } catch (...) {
    destroy();  // the destructor does not run for a constructor that throws
    throw;
  }
  log::info(std::string("Vulkan device: ") + properties_.deviceName +
            (instance_.validationEnabled() ? " (validation on)" : ""));
}

void Device::pickPhysicalDevice(const DeviceDesc& desc) {
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance_.vk(), &count, nullptr);
  std::vector<VkPhysicalDevice> physicals(count);
  vkEnumeratePhysicalDevices(instance_.vk(), &count, physicals.data());

  std::vector<DeviceCandidate> candidates;
  std::vector<std::uint32_t> families;
  for (VkPhysicalDevice physical : physicals) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(physical, &props);
    DeviceCandidate candidate;
    candidate.name = props.deviceName;
    candidate.type = props.deviceType;
    FeatureChain features;
    vkGetPhysicalDeviceFeatures2(physical, &features.core);
    const auto family = findQueueFamily(physical, desc.presentSurface);
    if (props.apiVersion < VK_API_VERSION_1_3) {
      candidate.unsuitableReason = "Vulkan 1.3 not supported";
    } else if (auto missing = missingRequiredFeature(features); !missing.empty()) {
      candidate.unsuitableReason = "feature " + missing + " not supported";
    } else if (!family) {
      candidate.unsuitableReason = desc.presentSurface != VK_NULL_HANDLE
                                       ? "no graphics+compute queue that can present"
                                       : "no graphics+compute queue with timestamps";
    } else if (desc.presentSurface != VK_NULL_HANDLE &&
               !hasExtension(physical, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) {
      candidate.unsuitableReason = "VK_KHR_swapchain not supported";
    } else {
      candidate.suitable = true;
    }
    candidates.push_back(candidate);
    families.push_back(family.value_or(0));
  }
  const std::string preference =
      desc.preference.empty() ? devicePreferenceFromEnvironment() : desc.preference;
  const std::size_t chosen = chooseDevice(candidates, preference);
  physical_ = physicals[chosen];
  queueFamily_ = families[chosen];
  presentEnabled_ = desc.presentSurface != VK_NULL_HANDLE;
  vkGetPhysicalDeviceProperties(physical_, &properties_);
}

void Device::createLogicalDevice() {
  FeatureChain supported;
  vkGetPhysicalDeviceFeatures2(physical_, &supported.core);

  FeatureChain enabled;
  enabled.core.features.shaderStorageImageExtendedFormats = VK_TRUE;
  enabled.core.features.samplerAnisotropy = supported.core.features.samplerAnisotropy;
  enabled.v12.timelineSemaphore = VK_TRUE;
  enabled.v12.hostQueryReset = VK_TRUE;
  enabled.v13.dynamicRendering = VK_TRUE;
  enabled.v13.synchronization2 = VK_TRUE;
  enabled.v13.maintenance4 = VK_TRUE;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  std::vector<const char*> extensions;
  if (presentEnabled_) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &enabled.core;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  GFX_CHECK(vkCreateDevice(physical_, &info, nullptr, &device_));
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

  if (instance_.debugUtilsEnabled()) {
    setObjectName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetDeviceProcAddr(device_, "vkSetDebugUtilsObjectNameEXT"));
    beginLabel_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetDeviceProcAddr(device_, "vkCmdBeginDebugUtilsLabelEXT"));
    endLabel_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetDeviceProcAddr(device_, "vkCmdEndDebugUtilsLabelEXT"));
  }
  gfx::setName(*this, queue_, "main queue");

  VkSemaphoreTypeCreateInfo timelineType{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
  timelineType.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
  timelineType.initialValue = 0;
  VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  semaphoreInfo.pNext = &timelineType;
  GFX_CHECK(vkCreateSemaphore(device_, &semaphoreInfo, nullptr, &timeline_));
  gfx::setName(*this, timeline_, "device timeline");

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  GFX_CHECK(vkCreateCommandPool(device_, &poolInfo, nullptr, &immediatePool_));
  gfx::setName(*this, immediatePool_, "immediate submit pool");
}

Device::~Device() {
  destroy();
}

void Device::destroy() noexcept {
  if (device_ == VK_NULL_HANDLE) return;
  vkDeviceWaitIdle(device_);  // returns (lost or not): nothing can run after it
  if (memory_) deferred_.collect(UINT64_MAX, device_, *memory_);
  memory_.reset();
  vkDestroyCommandPool(device_, immediatePool_, nullptr);
  vkDestroySemaphore(device_, timeline_, nullptr);
  vkDestroyDevice(device_, nullptr);
  device_ = VK_NULL_HANDLE;
}

void Device::check(VkResult result, const char* call, int line) const {
  if (result == VK_SUCCESS) return;
  if (result == VK_ERROR_DEVICE_LOST) lost_ = true;
  throwVulkanError(result, call, __FILE__, line);
}

// Submits with vkQueueSubmit and a VkTimelineSemaphoreSubmitInfo, not vkQueueSubmit2: with
// GPU-assisted validation, Debian's validation layer (1.3.239) loses track of the timeline
// signals of vkQueueSubmit2, and every later wait on them stalls for its 10 s timeout. For what
// the engine submits (whole command buffers, semaphores signalled at the end) the two are
// equivalent; waits keep their stage masks, which must be ones the original stage flags have.
std::uint64_t Device::submit(std::span<const VkCommandBuffer> commandBuffers,
                             std::span<const VkSemaphoreSubmitInfo> waits,
                             std::span<const VkSemaphoreSubmitInfo> extraSignals) {
  require(!lost_, "Device::submit", "the device was lost");
  // Fixed-size arrays: submission happens every frame and must not allocate.
  constexpr std::size_t kMaxWaits = 4;
  constexpr std::size_t kMaxSignals = 4;
  require(waits.size() <= kMaxWaits && extraSignals.size() < kMaxSignals, "Device::submit",
          "too many semaphores");
  VkSemaphore waitSemaphores[kMaxWaits];
  std::uint64_t waitValues[kMaxWaits];
  VkPipelineStageFlags waitStages[kMaxWaits];
  for (std::size_t i = 0; i < waits.size(); ++i) {
    require((waits[i].stageMask >> 32) == 0, "Device::submit",
            "a wait stage that only synchronization2 has");
    waitSemaphores[i] = waits[i].semaphore;
    waitValues[i] = waits[i].value;  // ignored for binary semaphores
    waitStages[i] = static_cast<VkPipelineStageFlags>(waits[i].stageMask);
  }
  const std::uint64_t value = lastSubmitted_ + 1;
  VkSemaphore signalSemaphores[kMaxSignals] = {timeline_};
  std::uint64_t signalValues[kMaxSignals] = {value};
  for (std::size_t i = 0; i < extraSignals.size(); ++i) {
    signalSemaphores[i + 1] = extraSignals[i].semaphore;
    signalValues[i + 1] = extraSignals[i].value;
  }
  const auto waitCount = static_cast<std::uint32_t>(waits.size());
  const auto signalCount = static_cast<std::uint32_t>(extraSignals.size() + 1);

  VkTimelineSemaphoreSubmitInfo values{VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO};
  values.waitSemaphoreValueCount = waitCount;
  values.pWaitSemaphoreValues = waitValues;
  values.signalSemaphoreValueCount = signalCount;
  values.pSignalSemaphoreValues = signalValues;
  VkSubmitInfo submitInfo{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submitInfo.pNext = &values;
  submitInfo.waitSemaphoreCount = waitCount;
  submitInfo.pWaitSemaphores = waitSemaphores;
  submitInfo.pWaitDstStageMask = waitStages;
  submitInfo.commandBufferCount = static_cast<std::uint32_t>(commandBuffers.size());
  submitInfo.pCommandBuffers = commandBuffers.data();
  submitInfo.signalSemaphoreCount = signalCount;
  submitInfo.pSignalSemaphores = signalSemaphores;
  check(vkQueueSubmit(queue_, 1, &submitInfo, VK_NULL_HANDLE), "vkQueueSubmit", __LINE__);
  lastSubmitted_ = value;
  return value;
}

std::uint64_t Device::completedValue() const {
  if (lost_) return lastSubmitted_;
  std::uint64_t value = 0;
  check(vkGetSemaphoreCounterValue(device_, timeline_, &value), "vkGetSemaphoreCounterValue",
        __LINE__);
  return value;
}

void Device::waitFor(std::uint64_t timelineValue) const {
  if (timelineValue == 0 || lost_) return;
  VkSemaphoreWaitInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
  info.semaphoreCount = 1;
  info.pSemaphores = &timeline_;
  info.pValues = &timelineValue;
  check(vkWaitSemaphores(device_, &info, UINT64_MAX), "vkWaitSemaphores", __LINE__);
}

void Device::waitIdle() {
  if (!lost_) check(vkDeviceWaitIdle(device_), "vkDeviceWaitIdle", __LINE__);
  // Idle: nothing submitted can still use a released object, and by contract nothing is being
  // recorded, so everything queued (including for the next submission) can go now.
  deferred_.collect(UINT64_MAX, device_, *memory_);
}

void Device::immediateSubmit(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = immediatePool_;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  GFX_CHECK(vkAllocateCommandBuffers(device_, &allocInfo, &cmd));
  gfx::setName(*this, cmd, "immediate submit");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  GFX_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  GFX_CHECK(vkEndCommandBuffer(cmd));
  const std::uint64_t value = submit(std::span<const VkCommandBuffer>(&cmd, 1));
  waitFor(value);
  vkFreeCommandBuffers(device_, immediatePool_, 1, &cmd);
  collectGarbage();
}

void Device::release(VkObjectType type, std::uint64_t handle, const Allocation& allocation) {
  // lastSubmitted_ + 1 is the submission that will carry the command buffer being recorded.
  deferred_.push(type, handle, allocation, lastSubmitted_ + 1);
}

void Device::collectGarbage() {
  deferred_.collect(completedValue(), device_, *memory_);
}

void Device::setName(VkObjectType type, std::uint64_t handle, const char* name) const {
  if (setObjectName_ == nullptr || handle == 0 || name == nullptr) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name;
  setObjectName_(device_, &info);
}

void Device::beginLabel(VkCommandBuffer cmd, const char* name) const {
  if (beginLabel_ == nullptr) return;
  VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  label.pLabelName = name;
  beginLabel_(cmd, &label);
}

void Device::endLabel(VkCommandBuffer cmd) const {
  if (endLabel_ != nullptr) endLabel_(cmd);
}

}  // namespace engine::gfx
