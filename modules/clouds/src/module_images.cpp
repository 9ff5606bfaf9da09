#include "module_images.h"

#include <algorithm>

#include "cloud_types.h"

namespace clouds::detail {
namespace {

constexpr VkFormat kNoiseFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kRadianceFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kDepthOutputFormat = VK_FORMAT_R32G32_SFLOAT;
// Trace-resolution samples: radiance, transmittance and both depths packed in one texel
// (cloud_temporal.h).
constexpr VkFormat kSampleFormat = VK_FORMAT_R32G32B32A32_UINT;
// Temporal upsampling's output-resolution history, written at every output pixel: 8 bytes
// (packOutputHistory()).
constexpr VkFormat kOutputHistoryFormat = VK_FORMAT_R32G32_UINT;
// Every image can be read back (the module's tests and tools); outputs also take clears (a
// provably clear sky is cleared, not marched) and histories transfers in (tests poison them).
constexpr VkImageUsageFlags kStorage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
constexpr VkImageUsageFlags kOutput =
    kStorage | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
constexpr VkImageUsageFlags kHistory = kStorage | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

// Whether `image` is exactly `extent` ({0, 0}: no image).
bool fitsExactly(const OwnedImage& image, VkExtent2D extent) {
  if (extent.width == 0 || extent.height == 0) return !image;
  return image && image.extent().width == extent.width && image.extent().height == extent.height;
}

VkExtent3D extent3(VkExtent2D e) {
  return {e.width, e.height, 1};
}

bool holds(const OwnedImage& image, VkExtent2D size) {
  return image && image.extent().width >= size.width && image.extent().height >= size.height;
}

// The larger of an image's current size and `wanted`, per axis: images only grow.
VkExtent2D grown(const OwnedImage& image, VkExtent2D wanted) {
  if (!image) return wanted;
  return {std::max(image.extent().width, wanted.width),
          std::max(image.extent().height, wanted.height)};
}

}  // namespace

ModuleImages::ModuleImages(const DeviceContext& device) : device_(device) {
  const auto s = static_cast<std::uint32_t>(shader::kShapeNoiseSize);
  const auto d = static_cast<std::uint32_t>(shader::kDetailNoiseSize);
  const auto c = static_cast<std::uint32_t>(shader::kCurlNoiseSize);
  const auto w = static_cast<std::uint32_t>(shader::kWeatherMapSize);
  const auto fine = static_cast<std::uint32_t>(shader::kWeatherMaxFineSize);
  const auto coarse = static_cast<std::uint32_t>(shader::kWeatherMaxCoarseSize);
  // The 3D noises hold their mip chains above level 0 (noiseLevelOrigin()): n x n x 3n/2.
  shapeNoise =
      make(VK_IMAGE_TYPE_3D, kNoiseFormat, {s, s, s + s / 2}, kStorage, "shape noise mip chain");
  detailNoise =
      make(VK_IMAGE_TYPE_3D, kNoiseFormat, {d, d, d + d / 2}, kStorage, "detail noise mip chain");
  curlNoise = make(VK_IMAGE_TYPE_2D, kNoiseFormat, {c, c, 1}, kStorage, "curl noise");
  for (std::uint32_t i = 0; i < 2; ++i) {
    weatherMaps[i] = make(VK_IMAGE_TYPE_2D, kNoiseFormat, {w, w, 1}, kStorage,
                          "weather map " + std::to_string(i));
  }
  weatherMaxFine =
      make(VK_IMAGE_TYPE_2D, kNoiseFormat, {fine, fine, 1}, kStorage, "weather maxima (fine)");
  weatherMaxCoarse = make(VK_IMAGE_TYPE_2D, kNoiseFormat, {coarse, coarse, 1}, kStorage,
                          "weather maxima (coarse)");
  depthPlaceholder =
      make(VK_IMAGE_TYPE_2D, VK_FORMAT_R32_SFLOAT, {1, 1, 1}, VK_IMAGE_USAGE_SAMPLED_BIT,
           "no host depth", VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  samplesPlaceholder =
      make(VK_IMAGE_TYPE_2D, kSampleFormat, {1, 1, 1}, kStorage, "no output history");
  hazePlaceholder = make(VK_IMAGE_TYPE_3D, kRadianceFormat, {1, 1, 1}, VK_IMAGE_USAGE_SAMPLED_BIT,
                         "no aerial perspective", VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  noHeroLight =
      make(VK_IMAGE_TYPE_3D, VK_FORMAT_R16_SFLOAT, {1, 1, 1}, kStorage, "no hero light volume");
  noDepthOutput = make(VK_IMAGE_TYPE_2D, kDepthOutputFormat, {1, 1, 1}, VK_IMAGE_USAGE_STORAGE_BIT,
                       "no cloud depth output");
}

OwnedImage ModuleImages::make(VkImageType type, VkFormat format, VkExtent3D extent,
                              VkImageUsageFlags usage, const std::string& name,
                              VkImageLayout layout) {
  OwnedImage image(device_, type, format, extent, usage, name);
  pendingLayouts_.push_back({image.image(), layout});
  return image;
}

void ModuleImages::replace(OwnedImage& slot, OwnedImage replacement,
                           std::optional<std::uint64_t> lastUse) {
  if (slot) {
    // Its first transition may not have been recorded yet: then nothing will record it.
    const VkImage old = slot.image();
    std::erase_if(pendingLayouts_, [old](const PendingLayout& p) { return p.image == old; });
    retired_.push_back({std::move(slot), lastUse});
  }
  slot = std::move(replacement);
}

bool ModuleImages::fit(const ImageSizes& sizes) const {
  // A depth output no longer wanted does not fit either: grow() frees it.
  const bool depthFits = sizes.depth.width == 0 ? !depth : holds(depth, sizes.depth);
  return holds(radiance, sizes.output) && depthFits && holds(sceneDistance, sizes.trace) &&
         holds(traceSamples, sizes.trace) && holds(history[0], sizes.trace) &&
         holds(history[1], sizes.trace) &&
         (!sizes.upsampling ||
          (holds(outputHistory[0], sizes.output) && holds(outputHistory[1], sizes.output))) &&
         (sizes.lightning.width == 0 || holds(lightningGlow, sizes.lightning)) &&
         (sizes.nearField.width == 0 ||
          (holds(nearSamples, sizes.nearField) && holds(nearHistory[0], sizes.nearField) &&
           holds(nearHistory[1], sizes.nearField))) &&
         (sizes.godRays.width == 0 ||
          (fitsExactly(godRayOcclusion, sizes.godRays) && fitsExactly(godRayMask, sizes.godRays) &&
           fitsExactly(godRayLight, sizes.godRays)));
}

bool ModuleImages::grow(const ImageSizes& sizes, std::optional<std::uint64_t> lastUse) {
  bool historyLost = false;
  if (!holds(radiance, sizes.output)) {
    const VkExtent3D e = extent3(grown(radiance, sizes.output));
    replace(radiance, make(VK_IMAGE_TYPE_2D, kRadianceFormat, e, kOutput, "radiance"), lastUse);
  }
  if (sizes.depth.width == 0) {
    if (depth) replace(depth, OwnedImage{}, lastUse);
  } else if (!holds(depth, sizes.depth)) {
    const VkExtent3D e = extent3(grown(depth, sizes.depth));
    replace(depth, make(VK_IMAGE_TYPE_2D, kDepthOutputFormat, e, kOutput, "cloud depth"), lastUse);
  }
  // A ping-pong pair of histories, remade together.
  const auto replacePair = [&](std::array<OwnedImage, 2>& pair, VkFormat format, VkExtent3D e,
                               const std::string& name) {
    for (std::uint32_t i = 0; i < 2; ++i) {
      replace(pair[i], make(VK_IMAGE_TYPE_2D, format, e, kHistory, name + std::to_string(i)),
              lastUse);
    }
  };
  const bool traceFits = holds(sceneDistance, sizes.trace) && holds(traceSamples, sizes.trace) &&
                         holds(history[0], sizes.trace) && holds(history[1], sizes.trace);
  if (!traceFits) {
    const VkExtent3D e = extent3(grown(sceneDistance, sizes.trace));
    replace(sceneDistance,
            make(VK_IMAGE_TYPE_2D, VK_FORMAT_R32_SFLOAT, e, kStorage, "scene distance (trace)"),
            lastUse);
    replace(traceSamples,
            make(VK_IMAGE_TYPE_2D, kSampleFormat, e, kStorage, "marched samples (trace)"), lastUse);
    replacePair(history, kSampleFormat, e, "history ");
    historyLost = true;
  }
  const bool upsamplingFits =
      holds(outputHistory[0], sizes.output) && holds(outputHistory[1], sizes.output);
  if (sizes.upsampling && !upsamplingFits) {
    replacePair(outputHistory, kOutputHistoryFormat, extent3(grown(outputHistory[0], sizes.output)),
                "output history ");
    historyLost = true;
  }
  const bool nearFieldFits = holds(nearSamples, sizes.nearField) &&
                             holds(nearHistory[0], sizes.nearField) &&
                             holds(nearHistory[1], sizes.nearField);
  if (sizes.nearField.width > 0 && !nearFieldFits) {
    const VkExtent3D e = extent3(grown(nearSamples, sizes.nearField));
    replace(nearSamples, make(VK_IMAGE_TYPE_2D, kSampleFormat, e, kStorage, "near field"), lastUse);
    replacePair(nearHistory, kSampleFormat, e, "near field history ");
    historyLost = true;
  }
  if (sizes.lightning.width > 0 && !holds(lightningGlow, sizes.lightning)) {
    const VkExtent3D e = extent3(grown(lightningGlow, sizes.lightning));
    replace(lightningGlow, make(VK_IMAGE_TYPE_2D, kRadianceFormat, e, kOutput, "lightning glow"),
            lastUse);
  }
  // Exactly the size wanted (read with samplers, whose uv spans the whole image); small, so
  // remade with the render extent.
  const bool godRaysFit = fitsExactly(godRayOcclusion, sizes.godRays) &&
                          fitsExactly(godRayMask, sizes.godRays) &&
                          fitsExactly(godRayLight, sizes.godRays);
  if (sizes.godRays.width > 0 && !godRaysFit) {
    const VkExtent3D e = extent3(sizes.godRays);
    replace(godRayOcclusion,
            make(VK_IMAGE_TYPE_2D, VK_FORMAT_R32_SFLOAT, e, kOutput, "god-ray occlusion"), lastUse);
    replace(godRayMask, make(VK_IMAGE_TYPE_2D, VK_FORMAT_R32_SFLOAT, e, kOutput, "god-ray mask"),
            lastUse);
    replace(godRayLight, make(VK_IMAGE_TYPE_2D, kRadianceFormat, e, kOutput, "god-ray light"),
            lastUse);
  }
  return historyLost;
}

bool ModuleImages::shadowFits(const ShadowExtents& extents) const {
  return fitsExactly(shadowMap, extents.atlas) && fitsExactly(shadowSpare, extents.spare);
}

bool ModuleImages::fitShadow(const ShadowExtents& extents, std::optional<std::uint64_t> lastUse) {
  if (shadowFits(extents)) return false;
  // Their layout depends on the cascades and resolution: the sizes are exact, not grown.
  const auto remake = [&](OwnedImage& image, VkExtent2D extent, const char* name) {
    if (fitsExactly(image, extent)) return;
    OwnedImage replacement;
    if (extent.width > 0 && extent.height > 0) {
      replacement = make(VK_IMAGE_TYPE_2D, kRadianceFormat, extent3(extent), kOutput, name);
    }
    replace(image, std::move(replacement), lastUse);
  };
  remake(shadowMap, extents.atlas, "cloud shadow map");
  remake(shadowSpare, extents.spare, "cloud shadow spare cascade");
  return true;
}

bool ModuleImages::fitSkyLight(bool wanted, std::optional<std::uint64_t> lastUse) {
  if (static_cast<bool>(skyLightMap) == wanted) return false;
  if (!wanted) {
    replace(skyLightClouds, OwnedImage{}, lastUse);
    replace(skyLightMap, OwnedImage{}, lastUse);
    return false;
  }
  const std::uint32_t w = shader::kSkyLightWidth;
  const std::uint32_t h = shader::kSkyLightHeight;
  replace(skyLightClouds,
          make(VK_IMAGE_TYPE_2D, kRadianceFormat, {w, h / 2, 1}, kStorage, "sky light clouds"),
          lastUse);
  replace(skyLightMap, make(VK_IMAGE_TYPE_2D, kRadianceFormat, {w, h, 1}, kOutput, "sky light"),
          lastUse);
  return true;
}

void ModuleImages::releaseRetired(std::uint64_t frameIndex, std::uint32_t framesInFlight) {
  std::erase_if(retired_, [&](const Retired& r) {
    return !r.lastUse || frameIndex >= *r.lastUse + framesInFlight;
  });
}

void ModuleImages::recordInitialLayouts(VkCommandBuffer cmd) {
  for (const PendingLayout& p : pendingLayouts_) {
    const bool sampled = p.layout == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    barrier(device_, cmd, p.image, VK_IMAGE_LAYOUT_UNDEFINED, p.layout, VK_PIPELINE_STAGE_2_NONE,
            VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            sampled ? VK_ACCESS_2_SHADER_SAMPLED_READ_BIT
                    : VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  }
  pendingLayouts_.clear();
}

MemoryUsage ModuleImages::memoryUsage() const {
  MemoryUsage m;
  m.noiseBytes = shapeNoise.bytes() + detailNoise.bytes() + curlNoise.bytes();
  m.weatherBytes = weatherMaps[0].bytes() + weatherMaps[1].bytes() + weatherMaxFine.bytes() +
                   weatherMaxCoarse.bytes();
  m.outputBytes = radiance.bytes() + depth.bytes();
  m.traceBytes = sceneDistance.bytes() + traceSamples.bytes() + history[0].bytes() +
                 history[1].bytes() + nearSamples.bytes() + nearHistory[0].bytes() +
                 nearHistory[1].bytes();
  m.upsamplingBytes = outputHistory[0].bytes() + outputHistory[1].bytes();
  m.shadowBytes = shadowMap.bytes() + shadowSpare.bytes();
  m.godRayBytes = godRayOcclusion.bytes() + godRayMask.bytes() + godRayLight.bytes();
  m.lightningBytes = lightningGlow.bytes();
  m.skyLightBytes = skyLightClouds.bytes() + skyLightMap.bytes();
  m.bufferBytes = depthPlaceholder.bytes() + samplesPlaceholder.bytes() + hazePlaceholder.bytes() +
                  noHeroLight.bytes() + noDepthOutput.bytes();
  for (const Retired& r : retired_) m.retiredBytes += r.image.bytes();
  return m;
}

}  // namespace clouds::detail
