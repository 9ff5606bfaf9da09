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
// shaderStorageImageExtendedFormats) and no extension; that set-up, its images and buffers and
// the camera conventions are ../../../examples/raw_vulkan_host.h, shared with the clouds
// module's example.
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
#include "raw_vulkan_host.h"

namespace {

// Vulkan set-up, images, buffers, barriers and the camera conventions (raw_vulkan_host.h).
using namespace example;

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

// --- The scene: a camera 300 m over a flat ground, looking towards a low sun -------------------

constexpr float kCameraAltitudeMetres = 300.0f;
constexpr float kNearMetres = 0.5f;
constexpr float kVerticalFov = 1.1f;  // radians
const glm::vec3 kForward = glm::normalize(glm::vec3(0.0f, 0.05f, -1.0f));
const glm::vec3 kTowardsSun = glm::normalize(glm::vec3(0.3f, 0.1f, -1.0f));
constexpr float kSunKilolux = 127.0f;  // at the top of the air; the ground's colour likewise

glm::mat4 viewOfTheCamera() {
  return viewMatrix(glm::vec3(0.0f, kCameraAltitudeMetres, 0.0f), kForward);
}

glm::mat4 projectionOfTheCamera(VkExtent2D extent) {
  return reversedZProjection(kVerticalFov, float(extent.width) / float(extent.height), kNearMetres);
}

// Per pixel: reversed-Z depth of the ground (0, the far plane, where the ray sees sky) and its
// colour, grey lit by the sun (half floats, RGBA).
void makeScene(VkExtent2D extent, std::vector<float>& depth, std::vector<std::uint16_t>& colour) {
  const glm::mat4 toView = glm::inverse(projectionOfTheCamera(extent));
  const glm::mat3 toWorld = glm::transpose(glm::mat3(viewOfTheCamera()));
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

// The host's colour and depth (in the formats CreateInfo defaults to: RGBA16F with storage use,
// D32) and one host-visible buffer that holds the scene to upload and the picture read back.
struct HostImages {
  Image colour;
  Image depth;
  HostBuffer staging;
  VkDeviceSize colourBytes = 0;  // the staging buffer's colour part; the depth follows it
};

HostImages createHostImages(const Gpu& gpu, VkExtent2D extent) {
  HostImages images;
  images.colour = createImage(gpu, VK_FORMAT_R16G16B16A16_SFLOAT, extent,
                              VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT);
  images.depth = createImage(gpu, VK_FORMAT_D32_SFLOAT, extent,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                             VK_IMAGE_ASPECT_DEPTH_BIT);
  std::vector<float> depths;
  std::vector<std::uint16_t> colours;
  makeScene(extent, depths, colours);
  images.colourBytes = colours.size() * sizeof(std::uint16_t);
  const VkDeviceSize depthBytes = depths.size() * sizeof(float);
  images.staging =
      createHostBuffer(gpu, images.colourBytes + depthBytes,
                       VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  std::memcpy(images.staging.mapped, colours.data(), images.colourBytes);
  std::memcpy(static_cast<char*>(images.staging.mapped) + images.colourBytes, depths.data(),
              depthBytes);
  return images;
}

void destroyHostImages(const Gpu& gpu, HostImages& images) {
  destroyHostBuffer(gpu, images.staging);
  destroyImage(gpu, images.colour);
  destroyImage(gpu, images.depth);
}

// --- Per frame ---------------------------------------------------------------------------------

// The scene into the host's images, in the layouts render() reads them in: the colour in
// GENERAL for its storage writes, the depth sampled read-only.
void recordSceneUpload(VkCommandBuffer cmd, const HostImages& images, VkExtent2D extent) {
  const VkImageAspectFlags c = VK_IMAGE_ASPECT_COLOR_BIT;
  const VkImageAspectFlags d = VK_IMAGE_ASPECT_DEPTH_BIT;
  imageBarrier(cmd, images.colour.image, c, VK_IMAGE_LAYOUT_UNDEFINED,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
               VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  imageBarrier(cmd, images.depth.image, d, VK_IMAGE_LAYOUT_UNDEFINED,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
               VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {c, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyBufferToImage(cmd, images.staging.buffer, images.colour.image,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  region.bufferOffset = images.colourBytes;
  region.imageSubresource.aspectMask = d;
  vkCmdCopyBufferToImage(cmd, images.staging.buffer, images.depth.image,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  imageBarrier(cmd, images.colour.image, c, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT,
               VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
               VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  imageBarrier(cmd, images.depth.image, d, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
               VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
               VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

void recordColourReadback(VkCommandBuffer cmd, const Image& colour, const HostBuffer& staging,
                          VkExtent2D extent) {
  imageBarrier(cmd, colour.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
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
                 const atmosphere::Settings& settings, const Submission& frame,
                 const HostImages& images, VkExtent2D extent, std::uint64_t index, bool last) {
  beginRecording(frame);
  recordSceneUpload(frame.cmd, images, extent);
  atmosphere::FrameInputs in;
  in.commandBuffer = frame.cmd;
  in.renderExtent = extent;
  in.view = viewOfTheCamera();
  in.projection = projectionOfTheCamera(extent);
  in.cameraPosition = glm::dvec3(0.0, kCameraAltitudeMetres, 0.0);
  in.sunDirection = kTowardsSun;
  in.sunIlluminance = glm::vec3(kSunKilolux);
  in.frameIndex = index;
  atmosphere::Error error;
  if (!sky.dispatch(in, air, settings, &error) ||
      !sky.render(frame.cmd, images.colour.view, images.depth.view,
                  VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, extent, &error)) {
    std::fprintf(stderr, "atmosphere_minimal_host: %s (%s)\n", error.message.c_str(),
                 atmosphere::errorCodeName(error.code));
    std::exit(1);
  }
  if (last) recordColourReadback(frame.cmd, images.colour, images.staging, extent);
  submitAndWait(gpu, frame);
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

// The module on the host's device, prepared for the picture's size; exits on an error.
std::unique_ptr<atmosphere::Context> createSky(const Gpu& gpu, const Options& options,
                                               const atmosphere::Parameters& air,
                                               const atmosphere::Settings& settings) {
  atmosphere::CreateInfo info;
  info.instance = gpu.instance;
  info.physicalDevice = gpu.physical;
  info.device = gpu.device;
  info.getInstanceProcAddr = vkGetInstanceProcAddr;
  info.getDeviceProcAddr = vkGetDeviceProcAddr;
  info.debugUtils = options.validation;  // the messenger's extension is enabled then
  info.maxRenderExtent = options.extent;
  info.maxFramesInFlight = 1;  // this host waits for each frame
  atmosphere::Error error;
  std::unique_ptr<atmosphere::Context> sky = atmosphere::Context::create(info, &error);
  if (!sky || !sky->prepare(air, settings, options.extent, &error)) {
    std::fprintf(stderr, "atmosphere_minimal_host: %s (%s)\n", error.message.c_str(),
                 atmosphere::errorCodeName(error.code));
    std::exit(1);
  }
  return sky;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const int bad = parseOptions(argc, argv, options)) return bad;
  programName() = "atmosphere_minimal_host";
  Gpu gpu = createGpu(options.validation);
  const atmosphere::Parameters air;  // Earth
  const atmosphere::Settings settings = atmosphere::settingsFor(atmosphere::Quality::Medium);
  bool written = false;
  {
    const std::unique_ptr<atmosphere::Context> sky = createSky(gpu, options, air, settings);
    HostImages images = createHostImages(gpu, options.extent);
    Submission frame = createSubmission(gpu);
    for (int i = 0; i < options.frames; ++i) {
      renderFrame(gpu, *sky, air, settings, frame, images, options.extent,
                  static_cast<std::uint64_t>(i), i + 1 == options.frames);
    }
    written = writePpm(options.output, static_cast<const std::uint16_t*>(images.staging.mapped),
                       options.extent);
    destroySubmission(gpu, frame);
    destroyHostImages(gpu, images);
  }  // the module's objects go before the device
  destroyGpu(gpu);
  if (!written) {
    std::fprintf(stderr, "atmosphere_minimal_host: cannot write %s\n", options.output.c_str());
    return 1;
  }
  std::printf("atmosphere_minimal_host: wrote %s (%u x %u, %d frame(s))\n", options.output.c_str(),
              options.extent.width, options.extent.height, options.frames);
  return validationMessages() > 0 ? 3 : 0;
}
