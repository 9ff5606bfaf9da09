#pragma once
// The images the module owns, and how they are sized.
//
// Fixed images (noise, weather maps and their maxima, placeholders) are made at creation.
// The rest scale with the render size and are made by prepare(): the outputs at the render
// extent (the depth only while something reads it: writesCloudDepth()), the trace images
// (scene distance, this frame's samples, two histories) at the trace extent, and the two
// output-resolution histories only for settings that upsample temporally.
// They only grow, to the largest size asked for on each axis; an image they replace is kept
// on a retire list until the frames in flight that may still use it have completed.
//
// Every new image starts in VK_IMAGE_LAYOUT_UNDEFINED; the next dispatch records its
// transition (recordInitialLayouts) before anything reads it.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "clouds/clouds.h"
#include "kit.h"

namespace clouds::detail {

// The shadow map's images: the cascade atlas and the spare cascade ({0, 0}: none).
struct ShadowExtents {
  VkExtent2D atlas{0, 0};
  VkExtent2D spare{0, 0};
};

struct ImageSizes {
  VkExtent2D output{0, 0};
  VkExtent2D trace{0, 0};
  bool upsampling = false;     // the output-resolution histories of temporal upsampling
  VkExtent2D godRays{0, 0};    // the god-ray occlusion image and mask ({0, 0}: none)
  VkExtent2D lightning{0, 0};  // the clouds' lightning glow, the trace's ({0, 0}: none)
  VkExtent2D depth{0, 0};      // the cloud depth output, the output's ({0, 0}: none)
  VkExtent2D nearField{0, 0};  // the near field's samples, the trace's ({0, 0}: none)
};

class ModuleImages {
 public:
  explicit ModuleImages(const DeviceContext& device);

  // Whether the images hold `sizes` already.
  bool fit(const ImageSizes& sizes) const;
  // Grows what does not fit `sizes`. `lastUse`: the last frame recorded with the current
  // images (none if no frame was). Returns true when a history image was replaced (its
  // contents are gone).
  bool grow(const ImageSizes& sizes, std::optional<std::uint64_t> lastUse);
  // Whether the shadow map's images are exactly `extents` ({0, 0}: none).
  bool shadowFits(const ShadowExtents& extents) const;
  // Replaces the shadow map's images by ones of exactly `extents` (none for {0, 0}) unless they
  // fit. Returns true when any was replaced (the map's contents are gone).
  bool fitShadow(const ShadowExtents& extents, std::optional<std::uint64_t> lastUse);
  // Makes the sky light's images (Settings::skyLight) when `wanted`, frees them when not.
  // Returns true when they were made (their contents are undefined until a frame writes them).
  bool fitSkyLight(bool wanted, std::optional<std::uint64_t> lastUse);
  // Frees retired images that no frame in flight can use any more when `frameIndex` records.
  void releaseRetired(std::uint64_t frameIndex, std::uint32_t framesInFlight);
  // Records the first layout transition of every image made since the last call.
  void recordInitialLayouts(VkCommandBuffer cmd);
  MemoryUsage memoryUsage() const;
  // Calls `visit` with each output the host reads: the radiance, and the depth when there is
  // one (writesCloudDepth()).
  template <typename Visit>
  void forEachOutput(Visit&& visit) const {
    visit(radiance);
    if (depth) visit(depth);
  }

  // Fixed.
  OwnedImage shapeNoise;
  OwnedImage detailNoise;
  OwnedImage curlNoise;
  std::array<OwnedImage, 2> weatherMaps;  // current and spare (weather_schedule.h)
  OwnedImage weatherMaxFine;
  OwnedImage weatherMaxCoarse;
  OwnedImage depthPlaceholder;    // 1 x 1 sampled R32F: no host depth
  OwnedImage samplesPlaceholder;  // 1 x 1 storage RGBA32UI: no output history
  OwnedImage hazePlaceholder;     // 1 x 1 x 1 sampled RGBA16F: no aerial perspective
  OwnedImage noHeroLight;         // 1 x 1 x 1 storage R32F: no hero clouds' light volume
  OwnedImage noDepthOutput;       // 1 x 1 storage RG32F: no cloud depth output
  // Sized by grow().
  OwnedImage radiance;                      // outputs, output resolution
  OwnedImage depth;                         // none without a cloud depth output (ImageSizes::depth)
  OwnedImage sceneDistance;                 // trace resolution, R32F
  OwnedImage traceSamples;                  // this frame's marched pixels (packed samples)
  std::array<OwnedImage, 2> history;        // reconstructed frames, ping-pong
  std::array<OwnedImage, 2> outputHistory;  // temporal upsampling's own samples, ping-pong
  OwnedImage shadowMap;    // the cloud shadow map's cascade atlas (Settings::shadowCascades)
  OwnedImage shadowSpare;  // one cascade in the making (Settings::shadowFramesPerCascade > 1)
  OwnedImage
      godRayOcclusion;       // what hides the sun, a quarter of the output (fxcontracts/god_rays.h)
  OwnedImage godRayMask;     // its radial blur (Outputs::godRayMask)
  OwnedImage godRayLight;    // what the upsample adds to the sky's pixels
  OwnedImage lightningGlow;  // the clouds' glow per unit of cloud, trace res
  OwnedImage nearSamples;    // the near field marched apart (packed samples), half trace res
  std::array<OwnedImage, 2> nearHistory;  // the near field resolved, ping-pong, half trace res
  // Fixed sizes, made by fitSkyLight().
  OwnedImage skyLightClouds;  // the clouds towards the sky light's upper half (radiance, T)
  OwnedImage skyLightMap;     // the sky light (Outputs::skyLight)

 private:
  struct Retired {
    OwnedImage image;
    std::optional<std::uint64_t> lastUse;
  };
  struct PendingLayout {
    VkImage image;
    VkImageLayout layout;
  };
  OwnedImage make(VkImageType type, VkFormat format, VkExtent3D extent, VkImageUsageFlags usage,
                  const std::string& name, VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL);
  void replace(OwnedImage& slot, OwnedImage replacement, std::optional<std::uint64_t> lastUse);

  const DeviceContext& device_;
  std::vector<Retired> retired_;
  std::vector<PendingLayout> pendingLayouts_;
};

}  // namespace clouds::detail
