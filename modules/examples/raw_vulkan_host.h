#pragma once
// What the effect modules' raw-Vulkan example hosts (modules/clouds/examples/minimal_host,
// modules/atmosphere/examples/minimal_host) share: an instance and device with exactly what the
// modules' READMEs require (Vulkan 1.3, synchronization2, shaderStorageImageExtendedFormats; the
// validation layer and a counting messenger only when asked), images and host-visible buffers,
// an image barrier, and the camera conventions the modules' FrameInputs take (a view matrix and
// a reversed-Z projection with an infinite far plane, Vulkan clip space). Header only, raw
// Vulkan and GLM: a host copies it with its example. Errors exit the program with a message.
#include <vulkan/vulkan.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <glm/glm.hpp>
#include <vector>

namespace example {

// The name the host's messages start with (and its VkApplicationInfo's).
inline const char*& programName() {
  static const char* name = "minimal_host";
  return name;
}

// --- Errors and validation -------------------------------------------------------------------

inline void vkCheck(VkResult result, const char* what) {
  if (result != VK_SUCCESS) {
    std::fprintf(stderr, "%s: %s failed (VkResult %d)\n", programName(), what,
                 static_cast<int>(result));
    std::exit(1);
  }
}

// Validation messages the messenger received (a host exits 3 when there were any).
inline int& validationMessages() {
  static int count = 0;
  return count;
}

inline VKAPI_ATTR VkBool32 VKAPI_CALL
countValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                       const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  ++validationMessages();
  std::fprintf(stderr, "validation: %s\n", data->pMessage);
  return VK_FALSE;
}

// --- Vulkan set-up ---------------------------------------------------------------------------

struct Gpu {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory{};
};

// With --validation, the layer and a messenger that prints and counts every message (exit 3).
inline void createInstance(Gpu& gpu, bool validation) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = programName();
  app.apiVersion = VK_API_VERSION_1_3;
  const char* layer = "VK_LAYER_KHRONOS_validation";
  const char* debugUtils = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instanceInfo.pApplicationInfo = &app;
  if (validation) {
    instanceInfo.enabledLayerCount = 1;
    instanceInfo.ppEnabledLayerNames = &layer;
    instanceInfo.enabledExtensionCount = 1;
    instanceInfo.ppEnabledExtensionNames = &debugUtils;
  }
  vkCheck(vkCreateInstance(&instanceInfo, nullptr, &gpu.instance), "vkCreateInstance");
  if (validation) {
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &countValidationMessage;
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(gpu.instance, "vkCreateDebugUtilsMessengerEXT"));
    vkCheck(create(gpu.instance, &messengerInfo, nullptr, &gpu.messenger), "debug messenger");
  }
}

inline void pickPhysicalDevice(Gpu& gpu) {
  // Any device with Vulkan 1.3 and a graphics+compute queue; real GPUs first.
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(gpu.instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(gpu.instance, &count, devices.data());
  int bestScore = -1;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(candidate, &props);
    if (props.apiVersion < VK_API_VERSION_1_3) continue;
    const int score = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 0 : 1;
    if (score > bestScore) {
      bestScore = score;
      gpu.physical = candidate;
    }
  }
  if (gpu.physical == VK_NULL_HANDLE) {
    std::fprintf(stderr, "%s: no Vulkan 1.3 device\n", programName());
    std::exit(1);
  }
  std::uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &familyCount, families.data());
  for (std::uint32_t i = 0; i < familyCount; ++i) {
    if ((families[i].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
        (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) {
      gpu.queueFamily = i;
      break;
    }
  }
}

inline void createDevice(Gpu& gpu) {
  // The module needs synchronization2 and storage images of extended formats (RG32F).
  VkPhysicalDeviceVulkan13Features features13{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  features13.synchronization2 = VK_TRUE;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &features13;
  features.features.shaderStorageImageExtendedFormats = VK_TRUE;
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = gpu.queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.pNext = &features;
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  vkCheck(vkCreateDevice(gpu.physical, &deviceInfo, nullptr, &gpu.device), "vkCreateDevice");
  vkGetDeviceQueue(gpu.device, gpu.queueFamily, 0, &gpu.queue);
  vkGetPhysicalDeviceMemoryProperties(gpu.physical, &gpu.memory);
}

inline Gpu createGpu(bool validation) {
  Gpu gpu;
  createInstance(gpu, validation);
  pickPhysicalDevice(gpu);
  createDevice(gpu);
  return gpu;
}

inline std::uint32_t memoryType(const Gpu& gpu, std::uint32_t bits, VkMemoryPropertyFlags flags) {
  for (std::uint32_t i = 0; i < gpu.memory.memoryTypeCount; ++i) {
    if ((bits & (1u << i)) && (gpu.memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
  }
  std::fprintf(stderr, "%s: no suitable memory type\n", programName());
  std::exit(1);
}

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

inline Image createImage(const Gpu& gpu, VkFormat format, VkExtent2D extent,
                         VkImageUsageFlags usage, VkImageAspectFlags aspect) {
  Image image;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.usage = usage;
  vkCheck(vkCreateImage(gpu.device, &info, nullptr, &image.image), "vkCreateImage");
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(gpu.device, image.image, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memoryType(gpu, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  vkCheck(vkAllocateMemory(gpu.device, &alloc, nullptr, &image.memory), "vkAllocateMemory");
  vkBindImageMemory(gpu.device, image.image, image.memory, 0);
  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image.image;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = format;
  viewInfo.subresourceRange = {aspect, 0, 1, 0, 1};
  vkCheck(vkCreateImageView(gpu.device, &viewInfo, nullptr, &image.view), "vkCreateImageView");
  return image;
}

struct HostBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
};

inline HostBuffer createHostBuffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage) {
  HostBuffer b;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  vkCheck(vkCreateBuffer(gpu.device, &info, nullptr, &b.buffer), "vkCreateBuffer");
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(gpu.device, b.buffer, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex =
      memoryType(gpu, req.memoryTypeBits,
                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  vkCheck(vkAllocateMemory(gpu.device, &alloc, nullptr, &b.memory), "vkAllocateMemory");
  vkBindBufferMemory(gpu.device, b.buffer, b.memory, 0);
  vkMapMemory(gpu.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped);
  return b;
}

inline void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                         VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage,
                         VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                         VkAccessFlags2 dstAccess) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = srcStage;
  b.srcAccessMask = srcAccess;
  b.dstStageMask = dstStage;
  b.dstAccessMask = dstAccess;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {aspect, 0, 1, 0, 1};
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

// The device, the messenger and the instance (after everything made on the device is gone).
inline void destroyGpu(Gpu& gpu) {
  vkDestroyDevice(gpu.device, nullptr);
  if (gpu.messenger != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(gpu.instance, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(gpu.instance, gpu.messenger, nullptr);
  }
  vkDestroyInstance(gpu.instance, nullptr);
}

inline void destroyImage(const Gpu& gpu, Image& image) {
  vkDestroyImageView(gpu.device, image.view, nullptr);
  vkDestroyImage(gpu.device, image.image, nullptr);
  vkFreeMemory(gpu.device, image.memory, nullptr);
}

inline void destroyHostBuffer(const Gpu& gpu, HostBuffer& buffer) {
  vkDestroyBuffer(gpu.device, buffer.buffer, nullptr);
  vkFreeMemory(gpu.device, buffer.memory, nullptr);
}

// --- One command buffer, submitted and waited for (one frame in flight) ------------------

struct Submission {
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
};

inline Submission createSubmission(const Gpu& gpu) {
  Submission submission;
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = gpu.queueFamily;
  vkCheck(vkCreateCommandPool(gpu.device, &poolInfo, nullptr, &submission.pool),
          "vkCreateCommandPool");
  VkCommandBufferAllocateInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  cmdInfo.commandPool = submission.pool;
  cmdInfo.commandBufferCount = 1;
  vkCheck(vkAllocateCommandBuffers(gpu.device, &cmdInfo, &submission.cmd),
          "vkAllocateCommandBuffers");
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  vkCheck(vkCreateFence(gpu.device, &fenceInfo, nullptr, &submission.fence), "vkCreateFence");
  return submission;
}

inline void beginRecording(const Submission& submission) {
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(submission.cmd, &begin), "vkBeginCommandBuffer");
}

inline void submitAndWait(const Gpu& gpu, const Submission& submission) {
  vkCheck(vkEndCommandBuffer(submission.cmd), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &submission.cmd;
  vkCheck(vkQueueSubmit(gpu.queue, 1, &submit, submission.fence), "vkQueueSubmit");
  vkCheck(vkWaitForFences(gpu.device, 1, &submission.fence, VK_TRUE, UINT64_MAX),
          "vkWaitForFences");
  vkCheck(vkResetFences(gpu.device, 1, &submission.fence), "vkResetFences");
}

inline void destroySubmission(const Gpu& gpu, Submission& submission) {
  vkDestroyFence(gpu.device, submission.fence, nullptr);
  vkDestroyCommandPool(gpu.device, submission.pool, nullptr);
}

// --- Camera conventions ----------------------------------------------------------------------

// World to view for a camera at `position` looking along `forward` (unit) with +Y up: view
// space looks down -Z.
inline glm::mat4 viewMatrix(const glm::vec3& position, const glm::vec3& forward) {
  const glm::vec3 r = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  const glm::vec3 u = glm::cross(r, forward);
  glm::mat4 v(1.0f);
  v[0][0] = r.x;
  v[1][0] = r.y;
  v[2][0] = r.z;
  v[0][1] = u.x;
  v[1][1] = u.y;
  v[2][1] = u.z;
  v[0][2] = -forward.x;
  v[1][2] = -forward.y;
  v[2][2] = -forward.z;
  v[3][0] = -glm::dot(r, position);
  v[3][1] = -glm::dot(u, position);
  v[3][2] = glm::dot(forward, position);
  return v;
}

// Reversed-Z (near 1, far 0), infinite far plane, Vulkan clip space (y down); `aspect` is
// width / height.
inline glm::mat4 reversedZProjection(float verticalFovRadians, float aspect, float nearMetres) {
  const float f = 1.0f / std::tan(verticalFovRadians * 0.5f);
  glm::mat4 p(0.0f);
  p[0][0] = f / aspect;
  p[1][1] = -f;
  p[3][2] = nearMetres;
  p[2][3] = -1.0f;
  return p;
}

}  // namespace example
