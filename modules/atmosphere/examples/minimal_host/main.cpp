// atmosphere minimal host: the smallest complete integration of the atmosphere module, with raw
// Vulkan and no engine. It
//   1. creates its own instance and device (Vulkan 1.3, synchronization2),
//   2. makes its scene on the CPU: a flat grey ground under a camera 300 m up looking towards a
//      low sun, as a reversed-Z depth buffer and an HDR colour image, and uploads them,
//   3. records atmosphere::Context::dispatch() (the LUTs, the sky, the haze) and render() (the
//      sky where the depth is the far plane, the haze over the ground elsewhere),
//   4. submits, reads the colour back, tonemaps it and writes a binary PPM image.
// main(), at the end of this file, reads as these steps; each is a function above it. It
// enables exactly what the module's README requires (Vulkan 1.3, synchronization2,
// shaderStorageImageExtendedFormats) and no extension. The Vulkan set-up has the shape of the
// clouds module's minimal host on purpose: each example is meant to be read and copied alone.
//
// Usage: atmosphere_minimal_host [--output FILE.ppm] [--width W] [--height H] [--frames N]
//                                [--validation]
//   --validation  (or CLOUDSCAPE_VALIDATION=1) the validation layer and a debug messenger
//                 (VK_EXT_debug_utils, then also CreateInfo::debugUtils): any message makes it
//                 exit 3
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>
#include <memory>
#include <string>
#include <vector>

#include "atmosphere/atmosphere.h"

namespace {

// --- Errors and validation -------------------------------------------------------------------

void vkCheck(VkResult result, const char* what) {
  if (result != VK_SUCCESS) {
    std::fprintf(stderr, "atmosphere_minimal_host: %s failed (VkResult %d)\n", what,
                 static_cast<int>(result));
    std::exit(1);
  }
}

int gValidationMessages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL countMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                            VkDebugUtilsMessageTypeFlagsEXT,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data,
                                            void*) {
  ++gValidationMessages;
  std::fprintf(stderr, "validation: %s\n", data->pMessage);
  return VK_FALSE;
}

struct Options {
  std::string output = "atmosphere_minimal_host.ppm";
  VkExtent2D extent{320, 180};
  int frames = 1;
  bool validation = false;
};

// Returns 0, or the exit code for a bad command line.
int parseOptions(int argc, char** argv, Options& options) {
  const char* env = std::getenv("CLOUDSCAPE_VALIDATION");
  options.validation = env != nullptr && std::strcmp(env, "1") == 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--output" && hasValue) {
      options.output = argv[++i];
    } else if (arg == "--width" && hasValue) {
      options.extent.width = static_cast<std::uint32_t>(std::atoi(argv[++i]));
    } else if (arg == "--height" && hasValue) {
      options.extent.height = static_cast<std::uint32_t>(std::atoi(argv[++i]));
    } else if (arg == "--frames" && hasValue) {
      options.frames = std::atoi(argv[++i]);
    } else if (arg == "--validation") {
      options.validation = true;
    } else {
      std::fprintf(stderr, "atmosphere_minimal_host: unknown or incomplete option %s\n", argv[i]);
      return 2;
    }
  }
  if (options.extent.width < 8 || options.extent.height < 8 || options.extent.width > 4096 ||
      options.extent.height > 4096 || options.frames < 1 || options.frames > 1000) {
    std::fprintf(stderr, "atmosphere_minimal_host: size in [8, 4096], frames in [1, 1000]\n");
    return 2;
  }
  return 0;
}

// --- Vulkan set-up -------------------------------------------------------------------------------

struct Gpu {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory{};
};

void createInstanceAndMessenger(Gpu& gpu, bool validation) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "atmosphere minimal host";
  app.apiVersion = VK_API_VERSION_1_3;
  const char* layer = "VK_LAYER_KHRONOS_validation";
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledLayerCount = validation ? 1 : 0;
  info.ppEnabledLayerNames = &layer;
  info.enabledExtensionCount = validation ? 1 : 0;
  info.ppEnabledExtensionNames = &extension;
  vkCheck(vkCreateInstance(&info, nullptr, &gpu.instance), "vkCreateInstance");
  if (!validation) return;
  VkDebugUtilsMessengerCreateInfoEXT messenger{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType =
      VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
  messenger.pfnUserCallback = &countMessage;
  const auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(gpu.instance, "vkCreateDebugUtilsMessengerEXT"));
  vkCheck(create(gpu.instance, &messenger, nullptr, &gpu.messenger), "debug messenger");
}

// The first Vulkan 1.3 device (lavapipe on a machine without a GPU) and its first queue family
// with compute and transfer.
void chooseDevice(Gpu& gpu) {
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(gpu.instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(gpu.instance, &count, devices.data());
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(candidate, &properties);
    if (properties.apiVersion >= VK_API_VERSION_1_3) {
      gpu.physical = candidate;
      break;
    }
  }
  if (gpu.physical == VK_NULL_HANDLE) {
    std::fprintf(stderr, "atmosphere_minimal_host: no Vulkan 1.3 device\n");
    std::exit(1);
  }
  std::uint32_t families = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &families, nullptr);
  std::vector<VkQueueFamilyProperties> properties(families);
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &families, properties.data());
  for (std::uint32_t i = 0; i < families; ++i) {
    if (properties[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
      gpu.queueFamily = i;
      break;
    }
  }
  vkGetPhysicalDeviceMemoryProperties(gpu.physical, &gpu.memory);
}

// Exactly what the module's README asks for: synchronization2 and extended storage formats.
void createDeviceWithTheModulesFeatures(Gpu& gpu) {
  VkPhysicalDeviceVulkan13Features features13{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  features13.synchronization2 = VK_TRUE;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &features13;
  features.features.shaderStorageImageExtendedFormats = VK_TRUE;
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = gpu.queueFamily;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &features;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  vkCheck(vkCreateDevice(gpu.physical, &info, nullptr, &gpu.device), "vkCreateDevice");
  vkGetDeviceQueue(gpu.device, gpu.queueFamily, 0, &gpu.queue);
}

std::uint32_t findMemory(const Gpu& gpu, std::uint32_t allowed, VkMemoryPropertyFlags wanted) {
  for (std::uint32_t i = 0; i < gpu.memory.memoryTypeCount; ++i) {
    const bool has = (gpu.memory.memoryTypes[i].propertyFlags & wanted) == wanted;
    if ((allowed & (1u << i)) != 0 && has) return i;
  }
  std::fprintf(stderr, "atmosphere_minimal_host: no memory type fits\n");
  std::exit(1);
}

// --- The host's images and a staging buffer ------------------------------------------------------

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

Image makeImage(const Gpu& gpu, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
                VkImageAspectFlags aspect) {
  Image made;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.usage = usage;
  vkCheck(vkCreateImage(gpu.device, &info, nullptr, &made.image), "vkCreateImage");
  VkMemoryRequirements needs{};
  vkGetImageMemoryRequirements(gpu.device, made.image, &needs);
  VkMemoryAllocateInfo allocation{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocation.allocationSize = needs.size;
  allocation.memoryTypeIndex =
      findMemory(gpu, needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  vkCheck(vkAllocateMemory(gpu.device, &allocation, nullptr, &made.memory), "vkAllocateMemory");
  vkBindImageMemory(gpu.device, made.image, made.memory, 0);
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = made.image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format;
  view.subresourceRange = {aspect, 0, 1, 0, 1};
  vkCheck(vkCreateImageView(gpu.device, &view, nullptr, &made.view), "vkCreateImageView");
  return made;
}

void destroyImage(const Gpu& gpu, Image& image) {
  vkDestroyImageView(gpu.device, image.view, nullptr);
  vkDestroyImage(gpu.device, image.image, nullptr);
  vkFreeMemory(gpu.device, image.memory, nullptr);
}

struct Staging {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
};

Staging makeStaging(const Gpu& gpu, VkDeviceSize bytes) {
  Staging made;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = bytes;
  info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  vkCheck(vkCreateBuffer(gpu.device, &info, nullptr, &made.buffer), "vkCreateBuffer");
  VkMemoryRequirements needs{};
  vkGetBufferMemoryRequirements(gpu.device, made.buffer, &needs);
  VkMemoryAllocateInfo allocation{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocation.allocationSize = needs.size;
  allocation.memoryTypeIndex =
      findMemory(gpu, needs.memoryTypeBits,
                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  vkCheck(vkAllocateMemory(gpu.device, &allocation, nullptr, &made.memory), "vkAllocateMemory");
  vkBindBufferMemory(gpu.device, made.buffer, made.memory, 0);
  vkCheck(vkMapMemory(gpu.device, made.memory, 0, VK_WHOLE_SIZE, 0, &made.mapped), "vkMapMemory");
  return made;
}

void transition(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                VkImageLayout to, VkPipelineStageFlags2 after, VkAccessFlags2 written,
                VkPipelineStageFlags2 before, VkAccessFlags2 read) {
  VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  barrier.srcStageMask = after;
  barrier.srcAccessMask = written;
  barrier.dstStageMask = before;
  barrier.dstAccessMask = read;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {aspect, 0, 1, 0, 1};
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

// --- The scene: a camera 300 m over a flat ground, looking towards a low sun -------------------

constexpr float kCameraAltitudeMetres = 300.0f;
constexpr float kNearMetres = 0.5f;
constexpr float kVerticalFov = 1.1f;  // radians
const glm::vec3 kForward = glm::normalize(glm::vec3(0.0f, 0.05f, -1.0f));
const glm::vec3 kTowardsSun = glm::normalize(glm::vec3(0.3f, 0.1f, -1.0f));
constexpr float kSunKilolux = 127.0f;  // at the top of the air; the ground's colour likewise

glm::mat4 viewMatrix() {  // rotation only: the module works camera-relative
  const glm::vec3 right = glm::normalize(glm::cross(kForward, glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(right, kForward);
  glm::mat4 view(1.0f);
  for (int i = 0; i < 3; ++i) {
    view[i][0] = right[i];
    view[i][1] = up[i];
    view[i][2] = -kForward[i];
  }
  return view;
}

glm::mat4 projectionMatrix(VkExtent2D extent) {  // reversed-Z, infinite far plane, y down
  const float f = 1.0f / std::tan(kVerticalFov * 0.5f);
  glm::mat4 projection(0.0f);
  projection[0][0] = f * float(extent.height) / float(extent.width);
  projection[1][1] = -f;
  projection[3][2] = kNearMetres;
  projection[2][3] = -1.0f;
  return projection;
}

// Per pixel: reversed-Z depth of the ground (0, the far plane, where the ray sees sky) and its
// colour, grey lit by the sun (half floats, RGBA).
void makeScene(VkExtent2D extent, std::vector<float>& depth, std::vector<std::uint16_t>& colour) {
  const glm::mat4 toView = glm::inverse(projectionMatrix(extent));
  const glm::mat3 toWorld = glm::transpose(glm::mat3(viewMatrix()));
  const glm::vec3 ground = glm::vec3(0.3f) * kSunKilolux * kTowardsSun.y / 3.14159265f;
  depth.assign(std::size_t{extent.width} * extent.height, 0.0f);
  colour.assign(depth.size() * 4, glm::packHalf1x16(0.0f));
  for (std::uint32_t y = 0; y < extent.height; ++y) {
    for (std::uint32_t x = 0; x < extent.width; ++x) {
      const glm::vec2 ndc((float(x) + 0.5f) / float(extent.width) * 2.0f - 1.0f,
                          (float(y) + 0.5f) / float(extent.height) * 2.0f - 1.0f);
      const glm::vec4 far = toView * glm::vec4(ndc, 0.5f, 1.0f);
      const glm::vec3 viewRay = glm::normalize(glm::vec3(far) / far.w);
      const glm::vec3 ray = toWorld * viewRay;
      if (ray.y >= 0.0f) continue;  // sky
      const float distance = kCameraAltitudeMetres / -ray.y;
      const std::size_t i = std::size_t{y} * extent.width + x;
      depth[i] = kNearMetres / (distance * -viewRay.z);  // reversed-Z of its view depth
      for (std::size_t c = 0; c < 3; ++c) {
        colour[i * 4 + c] = glm::packHalf1x16(ground[static_cast<int>(c)]);
      }
      colour[i * 4 + 3] = glm::packHalf1x16(1.0f);
    }
  }
}

// --- Per frame ---------------------------------------------------------------------------------

struct Frame {
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
};

Frame makeFrame(const Gpu& gpu) {
  Frame frame;
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = gpu.queueFamily;
  vkCheck(vkCreateCommandPool(gpu.device, &pool, nullptr, &frame.pool), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo allocation{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocation.commandPool = frame.pool;
  allocation.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocation.commandBufferCount = 1;
  vkCheck(vkAllocateCommandBuffers(gpu.device, &allocation, &frame.cmd), "command buffer");
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  vkCheck(vkCreateFence(gpu.device, &fence, nullptr, &frame.fence), "vkCreateFence");
  return frame;
}

// The scene into the host's images, in the layouts render() reads them in: the colour in
// GENERAL for its storage writes, the depth sampled read-only.
void recordSceneUpload(VkCommandBuffer cmd, const Staging& staging, VkDeviceSize colourBytes,
                       const Image& colour, const Image& depth, VkExtent2D extent) {
  const VkImageAspectFlags c = VK_IMAGE_ASPECT_COLOR_BIT;
  const VkImageAspectFlags d = VK_IMAGE_ASPECT_DEPTH_BIT;
  transition(cmd, colour.image, c, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
             VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
             VK_ACCESS_2_TRANSFER_WRITE_BIT);
  transition(cmd, depth.image, d, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
             VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
             VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {c, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyBufferToImage(cmd, staging.buffer, colour.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                         &region);
  region.bufferOffset = colourBytes;
  region.imageSubresource.aspectMask = d;
  vkCmdCopyBufferToImage(cmd, staging.buffer, depth.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                         &region);
  transition(cmd, colour.image, c, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
             VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
             VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
             VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  transition(cmd, depth.image, d, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
             VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
             VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
             VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

void recordColourReadback(VkCommandBuffer cmd, const Image& colour, const Staging& staging,
                          VkExtent2D extent) {
  transition(cmd, colour.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
             VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
             VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
             VK_ACCESS_2_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, colour.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1,
                         &region);
}

// One frame: the scene anew, the module's dispatch and render over it, and on the last frame
// the picture back to the host. Exits on a module error with its code's name.
void renderFrame(const Gpu& gpu, atmosphere::Context& sky, const atmosphere::Parameters& air,
                 const atmosphere::Settings& settings, const Frame& frame, const Staging& staging,
                 VkDeviceSize colourBytes, const Image& colour, const Image& depth,
                 VkExtent2D extent, std::uint64_t index, bool last) {
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(frame.cmd, &begin), "vkBeginCommandBuffer");
  recordSceneUpload(frame.cmd, staging, colourBytes, colour, depth, extent);
  atmosphere::FrameInputs in;
  in.commandBuffer = frame.cmd;
  in.renderExtent = extent;
  in.view = viewMatrix();
  in.projection = projectionMatrix(extent);
  in.cameraPosition = glm::dvec3(0.0, kCameraAltitudeMetres, 0.0);
  in.sunDirection = kTowardsSun;
  in.sunIlluminance = glm::vec3(kSunKilolux);
  in.frameIndex = index;
  atmosphere::Error error;
  if (!sky.dispatch(in, air, settings, &error) ||
      !sky.render(frame.cmd, colour.view, depth.view, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
                  extent, &error)) {
    std::fprintf(stderr, "atmosphere_minimal_host: %s (%s)\n", error.message.c_str(),
                 atmosphere::errorCodeName(error.code));
    std::exit(1);
  }
  if (last) recordColourReadback(frame.cmd, colour, staging, extent);
  vkCheck(vkEndCommandBuffer(frame.cmd), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &frame.cmd;
  vkCheck(vkQueueSubmit(gpu.queue, 1, &submit, frame.fence), "vkQueueSubmit");
  vkCheck(vkWaitForFences(gpu.device, 1, &frame.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  vkCheck(vkResetFences(gpu.device, 1, &frame.fence), "vkResetFences");
}

// The HDR colour (kcd/m^2) through an exposure for daylight and Reinhard, as sRGB-ish 8-bit.
bool writePpm(const std::string& path, const std::uint16_t* halves, VkExtent2D extent) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << extent.width << " " << extent.height << "\n255\n";
  const float exposure = 0.12f;
  for (std::size_t i = 0; i < std::size_t{extent.width} * extent.height; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float v = glm::unpackHalf1x16(halves[i * 4 + c]) * exposure;
      const float mapped = std::pow(v / (1.0f + v), 1.0f / 2.2f);
      out.put(static_cast<char>(std::clamp(mapped, 0.0f, 1.0f) * 255.0f + 0.5f));
    }
  }
  return bool(out);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const int bad = parseOptions(argc, argv, options)) return bad;
  Gpu gpu;
  createInstanceAndMessenger(gpu, options.validation);
  chooseDevice(gpu);
  createDeviceWithTheModulesFeatures(gpu);
  {
    const VkExtent2D extent = options.extent;
    atmosphere::CreateInfo info;
    info.instance = gpu.instance;
    info.physicalDevice = gpu.physical;
    info.device = gpu.device;
    info.getInstanceProcAddr = vkGetInstanceProcAddr;
    info.getDeviceProcAddr = vkGetDeviceProcAddr;
    info.debugUtils = options.validation;
    info.maxRenderExtent = extent;
    info.maxFramesInFlight = 1;  // this host waits for each frame
    atmosphere::Error error;
    const std::unique_ptr<atmosphere::Context> sky = atmosphere::Context::create(info, &error);
    const atmosphere::Parameters air;  // Earth
    const atmosphere::Settings settings = atmosphere::settingsFor(atmosphere::Quality::Medium);
    if (!sky || !sky->prepare(air, settings, extent, &error)) {
      std::fprintf(stderr, "atmosphere_minimal_host: %s (%s)\n", error.message.c_str(),
                   atmosphere::errorCodeName(error.code));
      return 1;
    }
    Image colour = makeImage(gpu, info.colorFormat, extent,
                             VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                 VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                             VK_IMAGE_ASPECT_COLOR_BIT);
    Image depth = makeImage(gpu, info.depthFormat, extent,
                            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                            VK_IMAGE_ASPECT_DEPTH_BIT);
    std::vector<float> depths;
    std::vector<std::uint16_t> colours;
    makeScene(extent, depths, colours);
    const VkDeviceSize colourBytes = colours.size() * sizeof(std::uint16_t);
    const Staging staging = makeStaging(gpu, colourBytes + depths.size() * sizeof(float));
    std::memcpy(staging.mapped, colours.data(), colourBytes);
    std::memcpy(static_cast<char*>(staging.mapped) + colourBytes, depths.data(),
                depths.size() * sizeof(float));
    const Frame frame = makeFrame(gpu);
    for (int i = 0; i < options.frames; ++i) {
      renderFrame(gpu, *sky, air, settings, frame, staging, colourBytes, colour, depth, extent,
                  static_cast<std::uint64_t>(i), i + 1 == options.frames);
    }
    if (!writePpm(options.output, static_cast<const std::uint16_t*>(staging.mapped), extent)) {
      std::fprintf(stderr, "atmosphere_minimal_host: cannot write %s\n", options.output.c_str());
      return 1;
    }
    vkDestroyFence(gpu.device, frame.fence, nullptr);
    vkDestroyCommandPool(gpu.device, frame.pool, nullptr);
    vkDestroyBuffer(gpu.device, staging.buffer, nullptr);
    vkFreeMemory(gpu.device, staging.memory, nullptr);
    destroyImage(gpu, colour);
    destroyImage(gpu, depth);
  }  // the module's objects go before the device
  vkDestroyDevice(gpu.device, nullptr);
  if (gpu.messenger != VK_NULL_HANDLE) {
    const auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(gpu.instance, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(gpu.instance, gpu.messenger, nullptr);
  }
  vkDestroyInstance(gpu.instance, nullptr);
  std::printf("atmosphere_minimal_host: wrote %s (%u x %u, %d frame(s))\n", options.output.c_str(),
              options.extent.width, options.extent.height, options.frames);
  return gValidationMessages > 0 ? 3 : 0;
}
