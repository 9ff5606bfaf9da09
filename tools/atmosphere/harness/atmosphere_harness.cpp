#include "atmosphere_harness.h"

#include <algorithm>
#include <cstring>
#include <glm/gtc/packing.hpp>
#include <span>

#include "engine/assets/image_metrics.h"
#include "engine/core/error.h"
#include "engine/gfx/barriers.h"
#include "engine/gfx/upload.h"
#include "engine/render/camera_math.h"

namespace atmosphere::tools {

using namespace engine;

namespace {

constexpr float kNearMetres = 0.5f;
constexpr VkFormat kColourFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

// The state the module leaves its outputs in between frames.
constexpr gfx::ImageState kModuleOutput{VK_IMAGE_LAYOUT_GENERAL,
                                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
// The host's colour as render() takes it: GENERAL, written by a transfer (the host's "draw").
constexpr gfx::ImageState kColourForModule{
    VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};

std::vector<glm::vec4> unpackHalves(std::span<const std::byte> bytes) {
  const auto* halves = reinterpret_cast<const std::uint16_t*>(bytes.data());
  std::vector<glm::vec4> texels(bytes.size() / 8);
  for (std::size_t i = 0; i < texels.size(); ++i) {
    texels[i] =
        glm::vec4(glm::unpackHalf1x16(halves[4 * i + 0]), glm::unpackHalf1x16(halves[4 * i + 1]),
                  glm::unpackHalf1x16(halves[4 * i + 2]), glm::unpackHalf1x16(halves[4 * i + 3]));
  }
  return texels;
}

}  // namespace

glm::vec3 sunDirection(const SkyView& v) {
  return render::directionFromAngles(v.sunAzimuthDegrees, v.sunElevationDegrees);
}

glm::mat4 viewMatrix(const SkyView& v) {
  // Camera-relative: the module uses the rotation only; the position goes in double.
  return render::lookTo(glm::vec3(0.0f), render::directionFromAngles(v.yawDegrees, v.pitchDegrees),
                        {0, 1, 0});
}

glm::mat4 projectionMatrix(const SkyView& v, VkExtent2D extent) {
  return render::perspectiveReversedZ(glm::radians(v.verticalFovDegrees),
                                      float(extent.width) / float(extent.height), kNearMetres);
}

AtmosphereHarness::AtmosphereHarness(gfx::Device& device, VkExtent2D maxExtent, bool passTimings)
    : device_(device) {
  CreateInfo info;
  info.instance = device.vkInstance();
  info.physicalDevice = device.physical();
  info.device = device.vk();
  info.getInstanceProcAddr = vkGetInstanceProcAddr;
  info.getDeviceProcAddr = vkGetDeviceProcAddr;
  info.maxRenderExtent = maxExtent;
  info.maxFramesInFlight = 1;               // every frame is submitted and waited for
  info.skyPassColorFormat = kColourFormat;  // drawSky() too
  info.passTimings = passTimings;
  Error error;
  context_ = Context::create(info, &error);
  if (!context_) throw engine::Error("atmosphere::Context::create: " + error.message);
}

AtmosphereHarness::~AtmosphereHarness() {
  device_.waitIdle();
}

void AtmosphereHarness::prepareHostImages(const SkyView& view, VkExtent2D extent) {
  if (!colour_ || colour_.extent().width != extent.width ||
      colour_.extent().height != extent.height) {
    colour_ = gfx::Image(
        device_,
        gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                       kColourFormat,
                       {extent.width, extent.height, 1},
                       1,
                       1,
                       VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                           VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                       "harness colour"});
    depth_ = gfx::Image(
        device_, gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                VK_FORMAT_D32_SFLOAT,
                                {extent.width, extent.height, 1},
                                1,
                                1,
                                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                "harness depth"});
  }
  // The host's frame: the ground drawn in one colour where the depth sees it.
  std::vector<float> depth(std::size_t{extent.width} * extent.height, 0.0f);
  if (view.groundDepth) {
    depth = render::flatGroundDepth(viewMatrix(view), projectionMatrix(view, extent), kNearMetres,
                                    view.position.y, extent.width, extent.height);
  }
  std::vector<std::uint16_t> colour(depth.size() * 4);
  for (std::size_t i = 0; i < depth.size(); ++i) {
    const glm::vec3 c = depth[i] > 0.0f ? view.groundColour : glm::vec3(0.0f);
    colour[4 * i + 0] = glm::packHalf1x16(c.r);
    colour[4 * i + 1] = glm::packHalf1x16(c.g);
    colour[4 * i + 2] = glm::packHalf1x16(c.b);
    colour[4 * i + 3] = glm::packHalf1x16(1.0f);
  }
  gfx::uploadToImage(device_, depth_, std::as_bytes(std::span(depth)),
                     {VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  gfx::uploadToImage(device_, colour_, std::as_bytes(std::span(colour)), kColourForModule);
}

template <typename Draw>
std::string AtmosphereHarness::record(const SkyView& view, const Parameters& parameters,
                                      const Settings& settings, VkExtent2D extent, Draw&& draw) {
  prepareHostImages(view, extent);
  Error error;
  if (!context_->prepare(parameters, settings, extent, &error)) return error.message;
  if (!timer_) timer_ = std::make_unique<gfx::GpuTimer>(device_, 1, "atmosphere harness");
  timer_->reset();
  bool ok = true;
  device_.immediateSubmit([&](VkCommandBuffer cmd) {
    FrameInputs in;
    in.commandBuffer = cmd;
    in.renderExtent = extent;
    in.view = viewMatrix(view);
    in.projection = projectionMatrix(view, extent);
    in.cameraPosition = view.position;
    in.sunDirection = sunDirection(view);
    in.sunIlluminance = view.sunIlluminance;
    in.frameIndex = frameIndex_;
    in.cloudShadow = view.cloudShadow;
    const std::uint32_t scope = timer_->begin(cmd, "atmosphere");
    ok = context_->dispatch(in, parameters, settings, &error) && draw(cmd, error);
    timer_->end(cmd, scope);
  });
  const auto scopes = timer_->resolve();
  lastGpuMilliseconds_ = scopes.empty() ? 0.0 : scopes[0].milliseconds;
  if (!ok) return error.message;
  ++frameIndex_;
  return {};
}

std::string AtmosphereHarness::tryRender(const SkyView& view, const Parameters& parameters,
                                         const Settings& settings, VkExtent2D extent) {
  return record(view, parameters, settings, extent, [&](VkCommandBuffer cmd, Error& error) {
    return context_->render(cmd, colour_.view(), view.groundDepth ? depth_.view() : VK_NULL_HANDLE,
                            VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, extent, &error);
  });
}

FloatImage AtmosphereHarness::render(const SkyView& view, const Parameters& parameters,
                                     const Settings& settings, VkExtent2D extent) {
  if (std::string error = tryRender(view, parameters, settings, extent); !error.empty()) {
    throw engine::Error("atmosphere: " + error);
  }
  FloatImage image;
  image.extent = colour_.extent();
  image.texels = unpackHalves(gfx::readbackImage(device_, colour_, kColourForModule));
  return image;
}

FloatImage AtmosphereHarness::drawSky(const SkyView& view, const Parameters& parameters,
                                      const Settings& settings, VkExtent2D extent) {
  const std::string problem =
      record(view, parameters, settings, extent, [&](VkCommandBuffer cmd, Error& error) {
        // The host's uploads (previous submissions) before the attachments are used.
        VkMemoryBarrier2 uploads{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        uploads.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        uploads.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
        uploads.dstStageMask = VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT;
        uploads.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
        VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dependency.memoryBarrierCount = 1;
        dependency.pMemoryBarriers = &uploads;
        vkCmdPipelineBarrier2(cmd, &dependency);
        VkRenderingAttachmentInfo colour{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        colour.imageView = colour_.view();
        colour.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
        colour.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
        colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth.imageView = depth_.view();
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_NONE;
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = {{0, 0}, extent};
        rendering.layerCount = 1;
        rendering.colorAttachmentCount = 1;
        rendering.pColorAttachments = &colour;
        rendering.pDepthAttachment = &depth;
        vkCmdBeginRendering(cmd, &rendering);
        const bool drawn = context_->drawSky(cmd, &error);
        vkCmdEndRendering(cmd);
        // Back to what readback and render() expect.
        uploads.srcStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        uploads.srcAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
        uploads.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        uploads.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
        vkCmdPipelineBarrier2(cmd, &dependency);
        return drawn;
      });
  if (!problem.empty()) throw engine::Error("atmosphere: " + problem);
  FloatImage image;
  image.extent = colour_.extent();
  image.texels = unpackHalves(gfx::readbackImage(device_, colour_, kColourForModule));
  return image;
}

FloatImage AtmosphereHarness::read(const OutputImage& output) {
  FloatImage image;
  image.extent = output.extent;
  image.texels = unpackHalves(
      gfx::readbackImage(device_, output.image, output.format, output.extent, kModuleOutput));
  return image;
}

SkyLighting AtmosphereHarness::lastSkyLighting() const {
  return frameIndex_ == 0 ? SkyLighting{} : context_->skyLighting(frameIndex_ - 1);
}

std::vector<PassTiming> AtmosphereHarness::lastPassTimings() const {
  return frameIndex_ == 0 ? std::vector<PassTiming>{} : context_->passTimings(frameIndex_ - 1);
}

double psnrRgb(const std::vector<glm::dvec3>& image, const std::vector<glm::dvec3>& reference) {
  double peak = 0.0;
  for (const glm::dvec3& r : reference) peak = std::max({peak, r.x, r.y, r.z});
  std::vector<float> a;
  std::vector<float> b;
  for (const glm::dvec3& v : image) a.insert(a.end(), {float(v.x), float(v.y), float(v.z)});
  for (const glm::dvec3& v : reference) b.insert(b.end(), {float(v.x), float(v.y), float(v.z)});
  return assets::compareImages(a, b, 3, 3).psnr(peak > 0.0 ? peak : 1.0);
}

}  // namespace atmosphere::tools
