// clouds minimal host: the smallest complete integration of the clouds module, with raw
// Vulkan and no engine. It
//   1. creates its own instance and device (Vulkan 1.3, synchronization2),
//   2. builds a synthetic scene on the CPU: a ground plane and three tall boxes, as a
//      reversed-Z depth buffer and a lit HDR colour image, and uploads them,
//   3. records clouds::Context::dispatchShadowMap(), reads the cloud shadow map back and lights
//      its scene through it on the CPU (ground_shadow.h: from the documentation alone),
//   4. records clouds::Context::dispatch() and composite() into its own command buffer,
//   5. submits, reads the colour back, tonemaps it and writes a binary PPM image.
// main(), at the end of this file, reads as these steps; each is a function above it.
// It enables exactly what the module's README requires (Vulkan 1.3, synchronization2,
// shaderStorageImageExtendedFormats) and no extension; that set-up, its images and buffers and
// the camera conventions are ../../../examples/raw_vulkan_host.h, which the atmosphere module's
// example shares.
//
// Usage: clouds_minimal_host [--output FILE.ppm] [--width W] [--height H] [--frames N]
//                            [--validation] [--no-clouds] [--no-cloud-shadows]
//                            [--claim-debug-utils]
//   --frames N            render N frames (the temporal reconstruction at work; default 1)
//   --validation          (or CLOUDSCAPE_VALIDATION=1) the validation layer and a debug
//                         messenger (VK_EXT_debug_utils, then also CreateInfo::debugUtils): any
//                         message makes it exit 3
//   --no-clouds           the scene alone, for comparison
//   --no-cloud-shadows    clouds, but the scene lit as if they cast no shadow
//   --claim-debug-utils   tell the module VK_EXT_debug_utils is enabled although it is not: a
//                         host bug, for the test that checks the module then trips validation
// Run it under the validation layer without enabling anything itself with
// VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation: the layer then prints to stdout.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>
#include <string>
#include <vector>

#include "clouds/clouds.h"
#include "ground_shadow.h"
#include "raw_vulkan_host.h"

namespace {

// Vulkan set-up, images, buffers, barriers and the camera conventions (raw_vulkan_host.h).
using namespace example;

// --- The synthetic scene -------------------------------------------------------------------------

struct Camera {
  glm::vec3 position{0.0f, 250.0f, 0.0f};
  glm::vec3 forward = glm::normalize(glm::vec3(0.0f, 0.14f, -1.0f));
  float verticalFov = glm::radians(70.0f);
  float nearPlane = 0.5f;
};

glm::mat4 viewMatrix(const Camera& c) {
  return example::viewMatrix(c.position, c.forward);
}

// Reversed-Z, infinite far plane, Vulkan clip space (y down).
glm::mat4 projectionMatrix(const Camera& c, float aspect) {
  return reversedZProjection(c.verticalFov, aspect, c.nearPlane);
}

// The ground plane's colour, and the albedo the clouds are told lights their bases from below.
constexpr glm::vec3 kGrassAlbedo(0.12f, 0.16f, 0.08f);

struct Box {
  glm::vec3 min;
  glm::vec3 max;
};

// Ray/box slab test: distance to the entry point or a negative value.
float hitBox(const glm::vec3& o, const glm::vec3& d, const Box& b) {
  const glm::vec3 inv = 1.0f / d;
  const glm::vec3 t0 = (b.min - o) * inv;
  const glm::vec3 t1 = (b.max - o) * inv;
  const glm::vec3 lo = glm::min(t0, t1);
  const glm::vec3 hi = glm::max(t0, t1);
  const float enter = std::max(std::max(lo.x, lo.y), lo.z);
  const float exit = std::min(std::min(hi.x, hi.y), hi.z);
  return exit >= std::max(enter, 0.0f) ? enter : -1.0f;
}

// Casts every pixel's ray against the ground and the boxes: reversed-Z depth (0 = sky) and a
// lit HDR colour (a sky gradient where nothing is hit), the sun's term through the clouds'
// shadow when there is one.
void buildScene(const Camera& camera, VkExtent2D extent, const glm::vec3& sun,
                const GroundShadow* shadow, std::vector<float>& depth,
                std::vector<std::uint16_t>& colour) {
  const Box boxes[] = {{{-700, 0, -3600}, {-100, 1500, -3000}},
                       {{400, 0, -2600}, {900, 900, -2200}},
                       {{-2400, 0, -6000}, {-1200, 2600, -5200}}};
  const glm::mat4 inverseProjection =
      glm::inverse(projectionMatrix(camera, float(extent.width) / float(extent.height)));
  const glm::mat3 viewToWorld = glm::transpose(glm::mat3(viewMatrix(camera)));
  for (std::uint32_t y = 0; y < extent.height; ++y) {
    for (std::uint32_t x = 0; x < extent.width; ++x) {
      const glm::vec2 ndc =
          (glm::vec2(x, y) + 0.5f) / glm::vec2(extent.width, extent.height) * 2.0f - 1.0f;
      const glm::vec4 v = inverseProjection * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 dir = glm::normalize(viewToWorld * (glm::vec3(v) / v.w));
      float t = dir.y < 0.0f ? -camera.position.y / dir.y : -1.0f;
      glm::vec3 normal(0, 1, 0);
      glm::vec3 albedo = kGrassAlbedo;
      for (const Box& box : boxes) {
        const float tb = hitBox(camera.position, dir, box);
        if (tb > 0.0f && (t < 0.0f || tb < t)) {
          t = tb;
          const glm::vec3 p = camera.position + dir * t;
          const glm::vec3 c = (box.min + box.max) * 0.5f;
          const glm::vec3 h = (box.max - box.min) * 0.5f;
          const glm::vec3 q = (p - c) / h;
          const glm::vec3 a = glm::abs(q);
          normal = a.x > a.y && a.x > a.z ? glm::vec3(glm::sign(q.x), 0, 0)
                   : a.y > a.z            ? glm::vec3(0, glm::sign(q.y), 0)
                                          : glm::vec3(0, 0, glm::sign(q.z));
          albedo = glm::vec3(0.25f, 0.22f, 0.2f);
        }
      }
      const std::size_t i = std::size_t{y} * extent.width + x;
      glm::vec3 radiance;
      if (t > 0.0f) {
        const float viewZ = t * glm::dot(dir, camera.forward);
        depth[i] = camera.nearPlane / viewZ;
        const float sunLight = shadow != nullptr ? shadow->transmittance(dir * t) : 1.0f;
        radiance = albedo * (3.0f * std::max(glm::dot(normal, sun), 0.0f) * sunLight + 0.6f);
      } else {
        depth[i] = 0.0f;
        radiance = glm::mix(glm::vec3(0.9f, 1.0f, 1.15f), glm::vec3(0.25f, 0.45f, 1.0f),
                            std::sqrt(std::max(dir.y, 0.0f)));
      }
      for (std::size_t c = 0; c < 3; ++c) {
        colour[4 * i + c] = glm::packHalf1x16(radiance[static_cast<int>(c)]);
      }
      colour[4 * i + 3] = glm::packHalf1x16(1.0f);
    }
  }
}

// Exposure, Reinhard and an sRGB-like gamma (enough for a preview), as a binary PPM: a format
// any image viewer opens, written without a library.
bool writePpm(const std::string& path, VkExtent2D extent, const std::uint16_t* halves) {
  std::vector<std::uint8_t> pixels(std::size_t{3} * extent.width * extent.height);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const float hdr = std::max(glm::unpackHalf1x16(halves[i / 3 * 4 + i % 3]), 0.0f) * 0.6f;
    const float ldr = std::pow(hdr / (1.0f + hdr), 1.0f / 2.2f);
    pixels[i] = static_cast<std::uint8_t>(std::clamp(ldr, 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << extent.width << " " << extent.height << "\n255\n";
  out.write(reinterpret_cast<const char*>(pixels.data()),
            static_cast<std::streamsize>(pixels.size()));
  return static_cast<bool>(out);
}

// --- Command line --------------------------------------------------------------------------

struct Options {
  std::string outputPath = "clouds_minimal_host.ppm";
  VkExtent2D extent{320, 180};
  bool validation = false;
  bool withClouds = true;
  bool cloudShadows = true;
  bool claimDebugUtils = false;
  int frames = 1;
};

// Reads the command line (and CLOUDSCAPE_VALIDATION) into `options`. Returns 0, or the exit
// code of a bad command line (2) once it has said what is wrong.
int parseOptions(int argc, char** argv, Options& options) {
  const char* env = std::getenv("CLOUDSCAPE_VALIDATION");
  options.validation = env != nullptr && env[0] != '\0' && env[0] != '0';
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc) {
      options.outputPath = argv[++i];
    } else if (arg == "--width" && i + 1 < argc) {
      options.extent.width = static_cast<std::uint32_t>(std::atoi(argv[++i]));
    } else if (arg == "--height" && i + 1 < argc) {
      options.extent.height = static_cast<std::uint32_t>(std::atoi(argv[++i]));
    } else if (arg == "--frames" && i + 1 < argc) {
      options.frames = std::atoi(argv[++i]);
    } else if (arg == "--validation") {
      options.validation = true;
    } else if (arg == "--no-clouds") {
      options.withClouds = false;
    } else if (arg == "--no-cloud-shadows") {
      options.cloudShadows = false;
    } else if (arg == "--claim-debug-utils") {
      options.claimDebugUtils = true;
    } else {
      std::fprintf(stderr,
                   "usage: %s [--output FILE.ppm] [--width W] [--height H] [--frames N] "
                   "[--validation] [--no-clouds] [--no-cloud-shadows] [--claim-debug-utils]\n",
                   argv[0]);
      return 2;
    }
  }
  const VkExtent2D extent = options.extent;
  if (extent.width < 8 || extent.height < 8 || extent.width > 8192 || extent.height > 8192) {
    std::fprintf(stderr, "minimal_host: --width/--height must be in [8, 8192]\n");
    return 2;
  }
  if (options.frames < 1 || options.frames > 10000) {
    std::fprintf(stderr, "minimal_host: --frames must be in [1, 10000]\n");
    return 2;
  }
  return 0;
}

// --- The host's images and submissions -------------------------------------------------------

std::size_t pixelCount(VkExtent2D extent) {
  return std::size_t{extent.width} * extent.height;
}

// The host's images: a reversed-Z depth buffer and an HDR colour image the module composites
// into (STORAGE usage, RGBA16F as CreateInfo::compositeColorFormat says); and the buffers that
// fill them from the CPU and read the colour back.
struct HostImages {
  Image depth;
  Image colour;
  HostBuffer depthUpload;
  HostBuffer colourUpload;
  HostBuffer readback;
};

HostImages createHostImages(const Gpu& gpu, VkExtent2D extent) {
  HostImages images;
  images.depth = createImage(gpu, VK_FORMAT_D32_SFLOAT, extent,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                             VK_IMAGE_ASPECT_DEPTH_BIT);
  images.colour = createImage(gpu, VK_FORMAT_R16G16B16A16_SFLOAT, extent,
                              VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT);
  const std::size_t pixels = pixelCount(extent);
  images.depthUpload = createHostBuffer(gpu, pixels * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  images.colourUpload = createHostBuffer(gpu, pixels * 8, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  images.readback = createHostBuffer(gpu, pixels * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  return images;
}

// The scene as the CPU made it last, and the camera and sun it is seen with.
struct Scene {
  Camera camera;
  glm::vec3 sun = glm::normalize(glm::vec3(-0.4f, 0.45f, -0.8f));
  std::vector<float> depth;
  std::vector<std::uint16_t> colour;
};

// The scene lit as if the clouds cast no shadow, copied into the upload buffers.
Scene buildUnshadowedScene(VkExtent2D extent, const HostImages& images) {
  Scene scene;
  const std::size_t pixels = pixelCount(extent);
  scene.depth.resize(pixels);
  scene.colour.resize(pixels * 4);
  buildScene(scene.camera, extent, scene.sun, nullptr, scene.depth, scene.colour);
  std::memcpy(images.depthUpload.mapped, scene.depth.data(), pixels * 4);
  std::memcpy(images.colourUpload.mapped, scene.colour.data(), pixels * 8);
  return scene;
}

// One command buffer, recorded, submitted and waited for in turn (maxFramesInFlight = 1).
// --- The clouds module -----------------------------------------------------------------------

// The clouds module: created from the host's handles and entry points, then (in main())
// prepared for the settings and size it will render (pipelines and images), outside any
// recording.
std::unique_ptr<clouds::Context> createClouds(const Gpu& gpu, const Options& options,
                                              clouds::Error* error) {
  clouds::CreateInfo info;
  info.instance = gpu.instance;
  info.physicalDevice = gpu.physical;
  info.device = gpu.device;
  info.getInstanceProcAddr = vkGetInstanceProcAddr;
  info.getDeviceProcAddr = vkGetDeviceProcAddr;
  // Only --validation enables the extension (--claim-debug-utils claims it all the same).
  info.debugUtils = options.validation || options.claimDebugUtils;
  info.depthFormat = VK_FORMAT_D32_SFLOAT;
  info.compositeColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  info.maxRenderExtent = options.extent;
  info.maxFramesInFlight = 1;
  info.reversedZ = true;
  return clouds::Context::create(info, error);
}

clouds::Settings cloudSettings(const Options& options) {
  clouds::Settings settings;  // the defaults, with a little more coverage: broken cumulus
  settings.coverage = 0.62f;
  settings.depthOutput = false;  // composite() reads the radiance only: no depth to store
  if (!options.withClouds || !options.cloudShadows) {
    settings.shadowCascades = 0;  // no map, no pass, no memory
  }
  return settings;
}

// The shadow map read back to the CPU: shadowMapResolution x cascades wide, RGBA16F.
struct ShadowReadback {
  HostBuffer buffer;
  VkExtent2D extent{0, 0};
};

ShadowReadback createShadowReadback(const Gpu& gpu, const clouds::Settings& settings) {
  ShadowReadback readback;
  readback.extent = {settings.shadowMapResolution * settings.shadowCascades,
                     settings.shadowMapResolution};
  readback.buffer = createHostBuffer(
      gpu,
      std::max<VkDeviceSize>(VkDeviceSize{readback.extent.width} * readback.extent.height * 8, 8),
      VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  return readback;
}

int reportError(const clouds::Error& error) {
  std::fprintf(stderr, "minimal_host: %s (%s)\n", error.message.c_str(),
               clouds::errorCodeName(error.code));
  return 1;
}

// --- A frame ---------------------------------------------------------------------------------

// What main() made for the frames.
struct Host {
  Options options;
  Gpu gpu;
  HostImages images;
  Scene scene;
  ShadowReadback shadowReadback;
  Submission submission;
};

clouds::FrameInputs frameInputs(const Host& host, int frame) {
  const Camera& camera = host.scene.camera;
  const VkExtent2D extent = host.options.extent;
  clouds::FrameInputs inputs;
  inputs.renderExtent = extent;
  inputs.depthView = host.images.depth.view;
  inputs.depthLayout = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
  inputs.view = viewMatrix(camera);
  inputs.projection = projectionMatrix(camera, float(extent.width) / float(extent.height));
  inputs.cameraPosition = glm::dvec3(camera.position);
  inputs.sunDirection = host.scene.sun;
  inputs.sunIlluminance = glm::vec3(12.0f, 11.5f, 10.5f);
  inputs.ambientTop = glm::vec3(0.45f, 0.6f, 0.95f);
  inputs.ambientBottom = glm::vec3(0.3f, 0.32f, 0.35f);
  inputs.groundAlbedo = kGrassAlbedo;  // cloud bases are lit from below by the grass
  inputs.timeSeconds = frame / 30.0;
  inputs.frameIndex = static_cast<std::uint64_t>(frame);
  return inputs;
}

void recordShadowMapReadback(VkCommandBuffer cmd, VkImage map, const ShadowReadback& readback) {
  imageBarrier(cmd, map, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
               VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
               VK_ACCESS_2_TRANSFER_READ_BIT);
  VkBufferImageCopy mapRegion{};
  mapRegion.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  mapRegion.imageExtent = {readback.extent.width, readback.extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, map, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer.buffer, 1,
                         &mapRegion);
  // Back to GENERAL, where the module keeps its outputs between frames, visible to how it
  // reads them (as storage and sampled images) and writes them.
  imageBarrier(cmd, map, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
               VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
               VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT |
                   VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

GroundShadow readGroundShadow(const ShadowReadback& readback,
                              const clouds::ShadowMapParameters& parameters) {
  GroundShadow shadow;
  shadow.width = readback.extent.width;
  shadow.height = readback.extent.height;
  shadow.parameters = parameters;
  const auto* halves = static_cast<const std::uint16_t*>(readback.buffer.mapped);
  shadow.texels.resize(std::size_t{shadow.width} * shadow.height);
  for (std::size_t i = 0; i < shadow.texels.size(); ++i) {
    shadow.texels[i] =
        glm::vec4(glm::unpackHalf1x16(halves[4 * i]), glm::unpackHalf1x16(halves[4 * i + 1]),
                  glm::unpackHalf1x16(halves[4 * i + 2]), glm::unpackHalf1x16(halves[4 * i + 3]));
  }
  return shadow;
}

// The clouds' shadow first, read back: the host lights its scene through it (on the CPU,
// ground_shadow.h), then uploads that colour in the frame's submission. A GPU host would read
// the map in its own shaders instead (fxcontracts/cloud_shadow.h), in the same submission.
bool lightSceneThroughCloudShadow(Host& host, clouds::Context& clouds,
                                  const clouds::Settings& settings, clouds::FrameInputs& inputs,
                                  clouds::Error* error) {
  beginRecording(host.submission);
  inputs.commandBuffer = host.submission.cmd;
  if (!clouds.dispatchShadowMap(inputs, settings, error)) return false;
  recordShadowMapReadback(host.submission.cmd, clouds.outputs().shadowMap.image,
                          host.shadowReadback);
  submitAndWait(host.gpu, host.submission);
  const GroundShadow shadow =
      readGroundShadow(host.shadowReadback, clouds.outputs().shadowParameters);
  Scene& scene = host.scene;
  buildScene(scene.camera, host.options.extent, scene.sun, &shadow, scene.depth, scene.colour);
  std::memcpy(host.images.colourUpload.mapped, scene.colour.data(),
              pixelCount(host.options.extent) * 8);
  return true;
}

VkBufferImageCopy wholeImage(VkImageAspectFlags aspect, VkExtent2D extent) {
  VkBufferImageCopy region{};
  region.imageSubresource = {aspect, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  return region;
}

// The depth never changes: it is uploaded once, then stays readable by the module.
void recordDepthUpload(VkCommandBuffer cmd, const HostImages& images, VkExtent2D extent) {
  const VkBufferImageCopy region = wholeImage(VK_IMAGE_ASPECT_DEPTH_BIT, extent);
  imageBarrier(cmd, images.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
               VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  vkCmdCopyBufferToImage(cmd, images.depthUpload.buffer, images.depth.image,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  imageBarrier(cmd, images.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
               VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

// The colour: the scene afresh, then GENERAL for the module's compute shaders.
void recordColourUpload(VkCommandBuffer cmd, const HostImages& images, VkExtent2D extent) {
  const VkBufferImageCopy region = wholeImage(VK_IMAGE_ASPECT_COLOR_BIT, extent);
  imageBarrier(cmd, images.colour.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
               VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
               VK_ACCESS_2_TRANSFER_WRITE_BIT);
  vkCmdCopyBufferToImage(cmd, images.colourUpload.buffer, images.colour.image,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  imageBarrier(cmd, images.colour.image, VK_IMAGE_ASPECT_COLOR_BIT,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
               VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
               VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

void recordColourReadback(VkCommandBuffer cmd, const HostImages& images, VkExtent2D extent) {
  const VkBufferImageCopy region = wholeImage(VK_IMAGE_ASPECT_COLOR_BIT, extent);
  imageBarrier(cmd, images.colour.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
               VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
               VK_ACCESS_2_TRANSFER_READ_BIT);
  vkCmdCopyImageToBuffer(cmd, images.colour.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         images.readback.buffer, 1, &region);
}

// One frame: with a shadow map, the clouds' shadow lights the scene first; then one submission
// uploads the scene, dispatches the clouds, composites them over it and reads the colour back.
bool renderFrame(Host& host, clouds::Context& clouds, const clouds::Settings& settings, int frame,
                 clouds::Error* error) {
  clouds::FrameInputs inputs = frameInputs(host, frame);
  if (settings.shadowCascades > 0 &&
      !lightSceneThroughCloudShadow(host, clouds, settings, inputs, error)) {
    return false;
  }
  const VkExtent2D extent = host.options.extent;
  const VkCommandBuffer cmd = host.submission.cmd;
  beginRecording(host.submission);
  inputs.commandBuffer = cmd;
  if (frame == 0) recordDepthUpload(cmd, host.images, extent);
  recordColourUpload(cmd, host.images, extent);
  if (host.options.withClouds && (!clouds.dispatch(inputs, settings, error) ||
                                  !clouds.composite(cmd, host.images.colour.view, extent, error))) {
    return false;
  }
  recordColourReadback(cmd, host.images, extent);
  submitAndWait(host.gpu, host.submission);
  return true;
}

// --- Teardown --------------------------------------------------------------------------------

// Everything main() made but the module, which goes first: the GPU is idle (fence waited).
void destroyHost(Host& host) {
  const Gpu& gpu = host.gpu;
  destroySubmission(gpu, host.submission);
  HostImages& images = host.images;
  for (HostBuffer* b :
       {&images.depthUpload, &images.colourUpload, &images.readback, &host.shadowReadback.buffer}) {
    destroyHostBuffer(gpu, *b);
  }
  for (Image* image : {&images.depth, &images.colour}) destroyImage(gpu, *image);
  destroyGpu(host.gpu);
}

}  // namespace

int main(int argc, char** argv) {
  Host host;
  if (const int badCommandLine = parseOptions(argc, argv, host.options)) return badCommandLine;
  const VkExtent2D extent = host.options.extent;
  host.gpu = createGpu(host.options.validation);
  host.images = createHostImages(host.gpu, extent);
  host.scene = buildUnshadowedScene(extent, host.images);

  clouds::Error error;
  std::unique_ptr<clouds::Context> clouds = createClouds(host.gpu, host.options, &error);
  const clouds::Settings settings = cloudSettings(host.options);
  host.shadowReadback = createShadowReadback(host.gpu, settings);
  if (!clouds || !clouds->prepare(settings, extent, &error)) return reportError(error);
  host.submission = createSubmission(host.gpu);

  // One frame per submission, waited for before the next (maxFramesInFlight = 1): the scene's
  // colour is uploaded afresh, then the clouds are dispatched and composited over it.
  for (int frame = 0; frame < host.options.frames; ++frame) {
    if (!renderFrame(host, *clouds, settings, frame, &error)) return reportError(error);
  }

  const std::string& outputPath = host.options.outputPath;
  const bool written =
      writePpm(outputPath, extent, static_cast<const std::uint16_t*>(host.images.readback.mapped));
  if (written) std::printf("minimal_host: wrote %s\n", outputPath.c_str());

  // Teardown: the GPU is idle (fence waited), so the module can go first.
  clouds.reset();
  destroyHost(host);
  if (!written) {
    std::fprintf(stderr, "minimal_host: cannot write %s\n", outputPath.c_str());
    return 1;
  }
  return validationMessages() > 0 ? 3 : 0;
}
