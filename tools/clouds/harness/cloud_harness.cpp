#include "cloud_harness.h"

#include "clamped_sampling.h"

#include "context_access.h"
#include "engine/assets/image_metrics.h"

#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>
#include <initializer_list>

#include "engine/core/error.h"
#include "engine/gfx/barriers.h"
#include "engine/gfx/upload.h"
#include "engine/render/camera_math.h"
#include "fxcontracts/cloud_shadow.h"
#include "tonemap_operator.h"

namespace {
// The map whose lookup runs (ShadowMapImage::transmittance, one thread at a time per map).
thread_local const clouds::tools::ShadowMapImage* tShadowMap = nullptr;

// `count` RGBA16F texels as floats.
std::vector<glm::vec4> unpackHalfTexels(const void* data, std::size_t count) {
  const auto* halves = static_cast<const std::uint16_t*>(data);
  std::vector<glm::vec4> texels(count);
  for (std::size_t i = 0; i < count; ++i) {
    texels[i] =
        glm::vec4(glm::unpackHalf1x16(halves[4 * i + 0]), glm::unpackHalf1x16(halves[4 * i + 1]),
                  glm::unpackHalf1x16(halves[4 * i + 2]), glm::unpackHalf1x16(halves[4 * i + 3]));
  }
  return texels;
}

// A module output of RGBA16F texels, read back from GENERAL (where it is left).
std::vector<glm::vec4> readHalfImage(engine::gfx::Device& device, VkImage image,
                                     VkExtent3D extent) {
  const engine::gfx::ImageState general{VK_IMAGE_LAYOUT_GENERAL,
                                        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                        VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT};
  const std::vector<std::byte> bytes =
      engine::gfx::readbackImage(device, image, VK_FORMAT_R16G16B16A16_SFLOAT, extent, general);
  return unpackHalfTexels(bytes.data(), std::size_t{extent.width} * extent.height);
}
}  // namespace

namespace fxcontracts::shader {
// The receivers' fetch, as a linear sampler clamped to the edge reads the atlas.
vec4 fetchCloudShadow(vec2 uv) {
  const auto& map = *tShadowMap;
  return clouds::tools::sampleLinearClamped(map.texels, map.width, map.height, uv);
}
// textureGather(map, uv, 3) on a clamped sampler.
vec4 gatherCloudShadowTerrain(vec2 uv) {
  const auto& map = *tShadowMap;
  const clouds::tools::Footprint f = clouds::tools::footprintAt(uv, map.width, map.height);
  const auto at = [&](int x, int y) {
    return clouds::tools::clampedTexel(map.texels, map.width, map.height, x, y).w;
  };
  return vec4(at(f.x, f.y + 1), at(f.x + 1, f.y + 1), at(f.x + 1, f.y), at(f.x, f.y));
}
}  // namespace fxcontracts::shader

namespace clouds::tools {

using namespace engine;

namespace {
constexpr float kNearMetres = 0.5f;
}  // namespace

glm::vec2 ShadowMapImage::lookup(const glm::vec3& relative) const {
  tShadowMap = this;
  fxcontracts::shader::CloudShadowParameters p;
  static_assert(sizeof(p) == sizeof(parameters));
  std::memcpy(&p, &parameters, sizeof(p));
  const glm::vec2 sun = fxcontracts::shader::cloudShadowAtPosition(p, relative);
  tShadowMap = nullptr;
  return sun;
}

glm::vec3 sunDirection(const CloudView& v) {
  return render::directionFromAngles(v.sunAzimuthDegrees, v.sunElevationDegrees);
}

glm::vec3 forwardDirection(const CloudView& v) {
  return render::directionFromAngles(v.yawDegrees, v.pitchDegrees);
}

glm::mat4 viewMatrix(const CloudView& v) {
  // Camera-relative world: the module only uses the rotation; the position goes in double.
  return render::lookTo(glm::vec3(0.0f), forwardDirection(v), {0, 1, 0});
}

glm::mat4 projectionMatrix(const CloudView& v, VkExtent2D extent) {
  glm::mat4 projection = render::perspectiveReversedZ(
      glm::radians(v.verticalFovDegrees), float(extent.width) / float(extent.height), kNearMetres);
  // A shift in normalised device coordinates (2 units across the image) after the divide by w.
  projection[2][0] += 2.0f * v.projectionJitterPixels.x / float(extent.width);
  projection[2][1] += 2.0f * v.projectionJitterPixels.y / float(extent.height);
  return projection;
}

PixelRays::PixelRays(const CloudView& view, VkExtent2D extent)
    : inverseProjection_(glm::inverse(projectionMatrix(view, extent))),
      viewToWorld_(glm::transpose(glm::mat3(viewMatrix(view)))),
      extent_(extent) {}

glm::vec3 PixelRays::direction(std::uint32_t x, std::uint32_t y) const {
  const glm::vec2 ndc =
      (glm::vec2(x, y) + 0.5f) / glm::vec2(extent_.width, extent_.height) * 2.0f - 1.0f;
  const glm::vec4 p = inverseProjection_ * glm::vec4(ndc, 1.0f, 1.0f);
  return glm::normalize(viewToWorld_ * (glm::vec3(p) / p.w));
}

clouds::Settings singleFrame(clouds::Settings settings) {
  settings.traceScale = 1.0f;
  settings.updateInterval = 1;
  settings.temporalReuse = false;
  return settings;
}

CloudHarness::CloudHarness(gfx::Device& device, VkExtent2D maxExtent, HarnessOptions options)
    : device_(device) {
  clouds::CreateInfo info;
  info.instance = device.vkInstance();
  info.physicalDevice = device.physical();
  info.device = device.vk();
  info.getInstanceProcAddr = vkGetInstanceProcAddr;
  info.getDeviceProcAddr = vkGetDeviceProcAddr;
  info.depthFormat = VK_FORMAT_D32_SFLOAT;
  info.maxRenderExtent = maxExtent;
  info.maxFramesInFlight = 2;
  info.reversedZ = true;
  info.noiseSeed = options.noiseSeed;
  info.workCounters = options.workCounters;
  info.passTimings = options.passTimings;
  clouds::Error error;
  context_ = clouds::Context::create(info, &error);
  if (!context_) throw engine::Error("clouds::Context::create: " + error.message);
}

CloudHarness::~CloudHarness() {
  device_.waitIdle();
}

namespace {

bool hasHostDepth(const CloudView& view) {
  return view.groundDepth || !view.hostDepth.empty();
}

}  // namespace

void CloudHarness::prepareDepth(const CloudView& view, VkExtent2D extent) {
  if (!depth_ || depth_.extent().width != extent.width || depth_.extent().height != extent.height) {
    depth_ = gfx::Image(device_,
                        gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                       VK_FORMAT_D32_SFLOAT,
                                       {extent.width, extent.height, 1},
                                       1,
                                       1,
                                       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                       "harness depth"});
  }
  // The view's own values, or a flat ground at y = 0, ray-cast on the CPU.
  if (!view.hostDepth.empty() && view.hostDepth.size() != std::size_t(extent.width) * extent.height)
    throw engine::Error("CloudView::hostDepth: one value a pixel of the extent");
  const std::vector<float> depth =
      !view.hostDepth.empty()
          ? view.hostDepth
          : render::flatGroundDepth(viewMatrix(view), projectionMatrix(view, extent), kNearMetres,
                                    view.position.y, extent.width, extent.height);
  depthValues_ = depth;
  gfx::uploadToImage(
      device_, depth_,
      std::span(reinterpret_cast<const std::byte*>(depth.data()), depth.size() * 4),
      gfx::ImageState{VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
}

clouds::FrameInputs CloudHarness::makeInputs(const CloudView& view, VkExtent2D extent,
                                             VkCommandBuffer cmd) {
  clouds::FrameInputs in;
  in.commandBuffer = cmd;
  in.renderExtent = extent;
  in.depthView = hasHostDepth(view) ? depth_.view() : VK_NULL_HANDLE;
  in.view = viewMatrix(view);
  in.projection = projectionMatrix(view, extent);
  in.cameraPosition = view.position;
  in.sunDirection = sunDirection(view);
  in.sunIlluminance = view.sunIlluminance;
  in.ambientTop = view.ambientTop;
  in.ambientBottom = view.ambientBottom;
  in.groundAlbedo = view.groundAlbedo;
  in.timeSeconds = view.timeSeconds;
  in.windDisplacementMetres = view.windDisplacementMetres;
  in.weatherView = view.weatherView;
  in.weatherBlendView = view.weatherBlendView;
  in.weatherBlend = view.weatherBlend;
  in.weatherRegions = view.weatherRegions;
  in.skyView = view.skyView;
  in.aerialPerspective = view.aerialPerspective;
  in.terrain = view.terrain;
  in.lightningFlashes = view.lightningFlashes;
  in.heroClouds = view.heroClouds;
  in.lightningBolts = view.lightningBolts;
  in.frameIndex = frameIndex_;
  in.reset = cutNext_;
  return in;
}

CloudFrame CloudHarness::renderAveraged(const CloudView& view, const clouds::Settings& settings,
                                        VkExtent2D extent, std::uint32_t frames) {
  cut();
  CloudFrame sum;
  for (std::uint32_t i = 0; i < frames; ++i) {
    const CloudFrame frame = render(view, settings, extent);
    if (i == 0) {
      sum = frame;
      continue;
    }
    for (std::size_t p = 0; p < frame.radiance.size(); ++p) {
      sum.radiance[p] += frame.radiance[p];
      sum.depth[p] += frame.depth[p];
    }
  }
  const float scale = 1.0f / static_cast<float>(std::max(frames, 1u));
  for (std::size_t p = 0; p < sum.radiance.size(); ++p) {
    sum.radiance[p] *= scale;
    sum.depth[p] *= scale;
  }
  return sum;
}

std::string CloudHarness::tryRender(const CloudView& view, const clouds::Settings& settings,
                                    VkExtent2D extent) {
  if (hasHostDepth(view)) {
    prepareDepth(view, extent);
  } else {
    depthValues_.clear();
  }
  clouds::Error error;
  // As a game would: prepare outside recording (cheap when nothing is new), then record.
  if (!context_->prepare(settings, extent, &error)) return error.message;
  bool ok = true;
  if (!timer_) timer_ = std::make_unique<gfx::GpuTimer>(device_, 1, "harness timer");
  timer_->reset();
  device_.immediateSubmit([&](VkCommandBuffer cmd) {
    lastInputs_ = makeInputs(view, extent, cmd);
    const std::uint32_t scope = timer_->begin(cmd, "clouds");
    // The terrain's shadow reaches the clouds through this frame's shadow map, and so do the
    // clouds' own shadow beyond the light cone and their shade on the ground that lights their
    // bases.
    if (view.terrain.heightView != VK_NULL_HANDLE || view.groundAlbedo) {
      ok = context_->dispatchShadowMap(lastInputs_, settings, &error);
    }
    ok = ok && context_->dispatch(lastInputs_, settings, &error);
    timer_->end(cmd, scope);
  });
  const auto scopes = timer_->resolve();
  lastGpuMilliseconds_ = scopes.empty() ? 0.0 : scopes[0].milliseconds;
  if (!ok) return error.message;
  cutNext_ = false;
  ++frameIndex_;
  return {};
}

CloudFrame CloudHarness::render(const CloudView& view, const clouds::Settings& settings,
                                VkExtent2D extent, std::uint32_t frames) {
  for (std::uint32_t i = 0; i < frames; ++i) {
    const std::string error = tryRender(view, settings, extent);
    if (!error.empty()) throw engine::Error("clouds dispatch: " + error);
  }
  const clouds::Outputs out = context_->outputs();
  const gfx::ImageState general{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
  CloudFrame frame;
  frame.extent = extent;
  const std::size_t pixels = std::size_t{extent.width} * extent.height;
  // Both outputs are 8 bytes a pixel (RGBA16F, RG32F); without a depth output, the radiance.
  struct Readback {
    VkImage image;
    gfx::Buffer buffer;
  };
  std::vector<Readback> readbacks;
  for (VkImage image : {out.radiance.image, out.depth.image}) {
    if (image == VK_NULL_HANDLE) continue;
    readbacks.push_back(
        {image, gfx::Buffer(device_, gfx::BufferDesc{pixels * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                     gfx::MemoryUsage::Readback,
                                                     "harness output readback"})});
  }
  device_.immediateSubmit([&](VkCommandBuffer cmd) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    const gfx::ImageState source{VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                 VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
    for (const Readback& r : readbacks) {
      gfx::imageBarrier(cmd, r.image, range, general, source);
      vkCmdCopyImageToBuffer(cmd, r.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, r.buffer.vk(), 1,
                             &region);
      // Back to GENERAL, as the module expects its outputs between frames.
      gfx::imageBarrier(cmd, r.image, range, source, general);
      gfx::bufferBarrier(cmd, r.buffer.vk(), VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                         VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                         VK_ACCESS_2_HOST_READ_BIT);
    }
  });
  frame.radiance = unpackHalfTexels(readbacks[0].buffer.mapped(), pixels);
  if (readbacks.size() > 1) {
    frame.depth.resize(pixels);
    std::memcpy(frame.depth.data(), readbacks[1].buffer.mapped(), pixels * 8);
  }
  return frame;
}

ShadowMapImage CloudHarness::renderShadowMap(const CloudView& view,
                                             const clouds::Settings& settings,
                                             std::uint32_t frames) {
  clouds::Error error;
  for (std::uint32_t i = 0; i < frames; ++i) {
    if (!context_->prepare(settings, {16, 16}, &error)) {
      throw engine::Error("clouds prepare: " + error.message);
    }
    bool ok = true;
    device_.immediateSubmit([&](VkCommandBuffer cmd) {
      lastInputs_ = makeInputs(view, {16, 16}, cmd);
      ok = context_->dispatchShadowMap(lastInputs_, settings, &error);
    });
    if (!ok) throw engine::Error("clouds dispatchShadowMap: " + error.message);
    cutNext_ = false;
    ++frameIndex_;
  }
  return readShadowMap();
}

ShadowMapImage CloudHarness::readShadowMap() {
  const clouds::Outputs out = context_->outputs();
  ShadowMapImage map;
  map.parameters = out.shadowParameters;
  if (out.shadowMap.image == VK_NULL_HANDLE) return map;
  const VkExtent3D extent = moduleImages().shadowMap.extent();
  map.width = extent.width;
  map.height = extent.height;
  map.texels = readHalfImage(device_, out.shadowMap.image, extent);
  return map;
}

SkyLightImage CloudHarness::readSkyLight() {
  const clouds::Outputs out = context_->outputs();
  SkyLightImage sky;
  if (out.skyLight.image == VK_NULL_HANDLE || frameIndex_ == 0) return sky;
  sky.measures = context_->skyLighting(frameIndex_ - 1);
  const VkExtent3D extent{clouds::kSkyLightExtent.width, clouds::kSkyLightExtent.height, 1};
  sky.width = extent.width;
  sky.height = extent.height;
  sky.texels = readHalfImage(device_, out.skyLight.image, extent);
  return sky;
}

float GodRayImages::occlusionAt(glm::vec2 uv) const {
  if (width == 0 || height == 0) return 1.0f;
  return sampleLinearClamped(occlusion, width, height, uv);
}

GodRayImages CloudHarness::readGodRays() {
  const clouds::Outputs out = context_->outputs();
  GodRayImages images;
  if (out.godRayMask.image == VK_NULL_HANDLE) return images;
  images.sun = out.godRaySun;
  images.blur = out.godRayBlur;
  const VkExtent3D extent = moduleImages().godRayMask.extent();
  const gfx::ImageState general{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT};
  const auto read = [&](VkImage image) {
    const std::vector<std::byte> bytes =
        gfx::readbackImage(device_, image, VK_FORMAT_R32_SFLOAT, extent, general);
    std::vector<float> values(std::size_t{extent.width} * extent.height);
    std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
    return values;
  };
  images.width = extent.width;
  images.height = extent.height;
  images.occlusion = read(moduleImages().godRayOcclusion.image());
  images.mask = read(out.godRayMask.image);
  return images;
}

namespace {

std::vector<std::uint8_t> readTexels(gfx::Device& device, VkImage image, VkExtent3D extent) {
  const gfx::ImageState general{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT};
  const std::vector<std::byte> bytes =
      gfx::readbackImage(device, image, VK_FORMAT_R8G8B8A8_UNORM, extent, general);
  const auto* first = reinterpret_cast<const std::uint8_t*>(bytes.data());
  return std::vector<std::uint8_t>(first, first + bytes.size());
}

// Fills each of the module's `images` (in GENERAL; null handles, images not made yet, skipped)
// with `value`, ordered after and before all other work.
void fillImages(gfx::Device& device, std::initializer_list<VkImage> images,
                const VkClearColorValue& value) {
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    const gfx::ImageState general{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                  VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT};
    const gfx::ImageState transfer{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                                   VK_ACCESS_2_TRANSFER_WRITE_BIT};
    for (VkImage image : images) {
      if (image == VK_NULL_HANDLE) continue;
      gfx::imageBarrier(cmd, image, range, general, transfer);
      vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_GENERAL, &value, 1, &range);
      gfx::imageBarrier(cmd, image, range, transfer, general);
    }
  });
}

}  // namespace

const clouds::detail::ModuleImages& CloudHarness::moduleImages() const {
  return clouds::detail::ContextAccess::impl(*context_).images();
}

std::vector<std::uint8_t> CloudHarness::readShapeNoise() {
  const auto& image = moduleImages().shapeNoise;
  return readTexels(device_, image.image(), image.extent());
}
std::vector<std::uint8_t> CloudHarness::readHeroNoise() {
  const clouds::detail::HeroNoise* noise =
      clouds::detail::ContextAccess::impl(*context_).heroNoise();
  if (noise == nullptr) return {};
  return readTexels(device_, noise->image().image(), noise->image().extent());
}
std::vector<std::uint8_t> CloudHarness::readDetailNoise() {
  const auto& image = moduleImages().detailNoise;
  return readTexels(device_, image.image(), image.extent());
}
std::vector<std::uint8_t> CloudHarness::readCurlNoise() {
  const auto& image = moduleImages().curlNoise;
  return readTexels(device_, image.image(), image.extent());
}
std::vector<std::uint8_t> CloudHarness::readWeatherMaxFine() {
  const auto& image = moduleImages().weatherMaxFine;
  return readTexels(device_, image.image(), image.extent());
}

void CloudHarness::poisonHistory() {
  // Packed samples (cloud_temporal.h): half-float NaN radiance, float NaN depths. The output
  // history (RG32UI) takes the first two words: its front depth a half-float NaN, and its top
  // bits an own-sample count of 7, so the poisoned texels claim to hold samples and must be
  // caught as not finite. The output histories exist only once settings that upsample
  // temporally were prepared.
  VkClearColorValue nan{};
  nan.uint32[0] = nan.uint32[1] = 0x7E007E00u;
  nan.uint32[2] = 0x7FC00000u;
  nan.uint32[3] = 0x7FC00003u;
  const clouds::detail::ModuleImages& images = moduleImages();
  fillImages(device_,
             {images.history[0].image(), images.history[1].image(), images.outputHistory[0].image(),
              images.outputHistory[1].image()},
             nan);
}

void CloudHarness::markRadianceOutput(glm::vec4 value) {
  fillImages(device_, {moduleImages().radiance.image()},
             VkClearColorValue{{value.r, value.g, value.b, value.a}});
}

clouds::WorkCounters CloudHarness::lastWorkCounters() const {
  return frameIndex_ == 0 ? clouds::WorkCounters{} : context_->workCounters(frameIndex_ - 1);
}

std::vector<clouds::PassTiming> CloudHarness::lastPassTimings() const {
  return frameIndex_ == 0 ? std::vector<clouds::PassTiming>{}
                          : context_->passTimings(frameIndex_ - 1);
}

std::vector<std::uint8_t> CloudHarness::readWeatherMap() {
  const auto& image = clouds::detail::ContextAccess::impl(*context_).weatherMap();
  return readTexels(device_, image.image(), image.extent());
}

std::vector<glm::vec3> tonemappedPixels(const CloudFrame& frame, const CloudView& view,
                                        float exposure) {
  std::vector<glm::vec3> pixels(std::size_t{frame.extent.width} * frame.extent.height);
  const PixelRays rays(view, frame.extent);
  for (std::uint32_t y = 0; y < frame.extent.height; ++y) {
    for (std::uint32_t x = 0; x < frame.extent.width; ++x) {
      const std::size_t i = std::size_t{y} * frame.extent.width + x;
      const glm::vec3 dir = rays.direction(x, y);
      const glm::vec3 background = dir.y > 0.0f
                                       ? glm::mix(glm::vec3(0.55f, 0.62f, 0.75f),
                                                  glm::vec3(0.15f, 0.28f, 0.65f), std::sqrt(dir.y))
                                       : glm::vec3(0.08f, 0.09f, 0.07f);
      const glm::vec4 c = frame.radiance[i];
      const glm::vec3 hdr = background * c.a + glm::vec3(c);
      const glm::vec3 mapped = engine::shaders::tonemap(hdr, exposure);
      for (int k = 0; k < 3; ++k) {
        pixels[i][k] = std::clamp(engine::shaders::linearToSrgb(mapped[k]), 0.0f, 1.0f);
      }
    }
  }
  return pixels;
}

assets::ImageRgba8 previewImage(const CloudFrame& frame, const CloudView& view, float exposure) {
  const std::vector<glm::vec3> pixels = tonemappedPixels(frame, view, exposure);
  assets::ImageRgba8 image{frame.extent.width, frame.extent.height, {}};
  image.pixels.resize(4 * pixels.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      image.pixels[4 * i + static_cast<std::size_t>(k)] =
          static_cast<std::uint8_t>(pixels[i][k] * 255.0f + 0.5f);
    }
    image.pixels[4 * i + 3] = 255;
  }
  return image;
}

engine::assets::ImageError imageError(const std::vector<glm::vec3>& image,
                                      const std::vector<glm::vec3>& reference) {
  return engine::assets::compareImages(
      std::span(reinterpret_cast<const float*>(image.data()), image.size() * 3),
      std::span(reinterpret_cast<const float*>(reference.data()), reference.size() * 3), 3, 3);
}

double psnr(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b, double peak) {
  return engine::assets::compareImages(
             std::span(reinterpret_cast<const float*>(a.data()), a.size() * 4),
             std::span(reinterpret_cast<const float*>(b.data()), b.size() * 4), 4, 4)
      .psnr(peak);
}

}  // namespace clouds::tools
