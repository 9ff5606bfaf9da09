#pragma once
// clouds: Nubis-style real-time volumetric clouds as a drop-in Vulkan module.
//
// Shaped like a FidelityFX effect:
//   1. clouds::Context::create(CreateInfo)          once, with the host's device and formats;
//   2. context->prepare(Settings, renderExtent)     outside command recording, whenever the
//      settings or the render size change: builds pipelines and sizes images (cheap when
//      nothing is new, so a host may call it every frame);
//   3. context->dispatch(FrameInputs, Settings)     every frame: records compute work into the
//      host's command buffer (never submits, waits, presents, creates or allocates);
//   4. context->outputs()                           the module's images for the host to read,
//      or context->composite(...)                   to apply the clouds over a host colour image.
// A host whose scene is shadowed by the clouds also calls, each frame before the passes that
// read it (typically before its scene pass, and before dispatch()),
//      context->dispatchShadowMap(FrameInputs, Settings)   the cloud shadow map (Outputs).
//
// Ownership: the host owns the instance, device, queue, command buffers, submission, its depth
// and colour images. The module owns its pipelines, noise textures, weather map, uniform
// buffers, temporal history and output images, and allocates their memory itself (a few
// dozen allocations; memoryUsage() reports them).
//
// Conventions: metres, seconds; Y up; right-handed; world directions as unit vectors; the sun
// direction points towards the sun; Vulkan clip space (y down, depth in [0, 1]), reversed-Z or
// not per CreateInfo. The cloud layer is a spherical shell around a planet whose centre lies
// straight below the camera, so the host's world is a flat map with y = altitude above sea
// level. Light is in the host's radiometric units: FrameInputs::sunIlluminance is an
// illuminance (e.g. lux), the ambient inputs and every radiance output are radiances in the
// matching unit per steradian (e.g. cd/m^2 = lux/sr), unclamped HDR.
//
// Temporal state is the module's: it remembers the camera, sun and time its history was made
// with, and reprojects from them; the host passes only the current frame (and `reset` on a
// camera cut). The module also owns its ray jitter (Settings::jitter), so pass the projection
// without any TAA jitter of the host.
//
// Requirements: Vulkan 1.3 with synchronization2 and shaderStorageImageExtendedFormats
// enabled; nothing optional (see CreateInfo::debugUtils). Thread safety: a Context is used
// from one thread at a time. Errors never throw: each call returns false (or nullptr) and
// fills an Error with a code hosts can branch on and a message naming the field at fault.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace clouds {

// What went wrong, for hosts to branch on; Error::message says which field or call, and why.
enum class ErrorCode : std::uint32_t {
  None = 0,
  InvalidCreateInfo,  // a CreateInfo field is missing or out of range
  MissingFunction,    // the proc-addr functions lack an entry point the module needs
  UnsupportedDevice,  // the device lacks a format feature the module needs
  OutOfMemory,        // a Vulkan allocation failed (host, device or descriptor-pool memory)
  VulkanFailure,      // another Vulkan call failed (the message names it and its VkResult)
  InvalidSettings,    // a Settings field is out of range (validateSettings())
  InvalidInputs,      // a FrameInputs field, or a composite() argument, is invalid
  NotPrepared,        // dispatch() needs prepare() with these settings or this extent first
  InvalidAsset,       // a cloud asset (clouds/nvdf.h) is malformed: the message names the file
};
const char* errorCodeName(ErrorCode code);

struct Error {
  ErrorCode code = ErrorCode::None;
  std::string message;
};

struct CreateInfo {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  // Entry points: the module loads every function it uses through these, so it works with
  // any loader setup (static linking, volk, ...).
  PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
  PFN_vkGetDeviceProcAddr getDeviceProcAddr = nullptr;
  // True only when the host enabled VK_EXT_debug_utils on the instance: the module then names
  // its objects ("clouds: ...") and labels its passes for debuggers and validation messages.
  // Loaders hand out these entry points even when the extension is off, and calling them then
  // is a validation error, so the module never uses them unless told.
  bool debugUtils = false;

  // Format of the depth views passed in FrameInputs (read with texelFetch, depth aspect).
  VkFormat depthFormat = VK_FORMAT_D32_SFLOAT;
  // Format of the colour image composite() writes (STORAGE usage); VK_FORMAT_UNDEFINED: no
  // composite helper. Only R16G16B16A16_SFLOAT is supported.
  VkFormat compositeColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  // The largest render extent prepare() and dispatch() will be given, [1, 16384] per side.
  // A bound, not an allocation: images are sized by prepare() to what is used.
  VkExtent2D maxRenderExtent{1920, 1080};
  // Frames the host may have in flight: per-frame descriptors and uniforms are ring-buffered
  // over this many slots by FrameInputs::frameIndex. The host must have waited for frame
  // (frameIndex - maxFramesInFlight) before recording frameIndex. [1, 8]
  std::uint32_t maxFramesInFlight = 2;
  // Depth convention of the host: reversed-Z means near = 1 and sky/far = 0.
  bool reversedZ = true;
  // Seed of the procedural noise textures and weather map (same seed, same clouds).
  std::uint32_t noiseSeed = 1;
  // Count the march's work (samples, rays, early exits) for workCounters(); costs atomics.
  bool workCounters = false;
  // Timestamp each pass for passTimings(); a few timestamp queries and execution barriers per
  // frame (passes cannot overlap while timed).
  bool passTimings = false;
};

// GPU time of one of the module's passes in a frame (CreateInfo::passTimings). A frame has, in
// recording order: "noise" (its first frame only), "weather" (frames that make or resample a
// weather map), "shadow map" (dispatchShadowMap() with cascades due), "terrain shadow" (the
// same, with FrameInputs::terrain), "sky ambient" (with FrameInputs::skyView or groundAlbedo),
// then either "clear sky" (nothing to march; then "god rays" too, with godRaySamples > 0) or
// "scene distance", "march", "lightning" (with this frame's flashes), "reconstruct", "god rays"
// (godRaySamples > 0), "upsample", "lightning bolts" (with this frame's bolts); last "sky light"
// (Settings::skyLight).
struct PassTiming {
  const char* name = "";  // static storage: valid for the life of the program
  double milliseconds = 0.0;
};

// What the march did in one frame (CreateInfo::workCounters).
struct WorkCounters {
  std::uint64_t viewSamples = 0;    // density samples along view rays (the near field's too)
  std::uint64_t lightSamples = 0;   // density samples towards the sun (the near field's too)
  std::uint64_t tracedPixels = 0;   // rays the tiles marched (edge rays included)
  std::uint64_t edgeRays = 0;       // of which edge rays (Settings::edgeRays)
  std::uint64_t nearFieldRays = 0;  // rays of the near field (Settings::nearFieldMetres)
  std::uint64_t earlyExits = 0;     // rays ended by the transmittance cutoff
  std::uint64_t skippedCells = 0;   // empty weather cells jumped over
};

// How the last dispatch reconstructed the frame.
struct FrameReport {
  VkExtent2D traceExtent{0, 0};  // {0, 0} on a clear-sky frame (nothing marched)
  std::uint32_t tileSize = 0;    // one pixel per tileSize x tileSize tile was marched; 0 on a
                                 //   clear-sky frame
  bool historyUsed = false;      // last frame's result was reprojected
  bool insideLayer = false;      // the camera was in or near the cloud layer
  // Why the history was not used ("" when it was). Static storage: valid for the life of the
  // program.
  const char* resetReason = "";
  // The shadow-map cascades this frame's dispatchShadowMap() made (bit c: cascade c).
  std::uint32_t shadowCascadesMade = 0;
  // The camera was in or near a hero cloud's box. Moving in it (or in the layer), the march
  // refreshes more pixels a frame: the cloud all around changes from frame to frame.
  bool insideHeroCloud = false;
  // The near field was marched apart this frame (Settings::nearFieldMetres: the camera was
  // within that distance of the layer or of a hero cloud's box).
  bool nearField = false;
};

// The GPU memory the module holds, by purpose (bytes of its VkDeviceMemory allocations).
struct MemoryUsage {
  std::uint64_t noiseBytes = 0;       // shape, detail and curl noise
  std::uint64_t weatherBytes = 0;     // two weather maps (current, next) and their maxima
  std::uint64_t outputBytes = 0;      // radiance and depth at the prepared render extent
  std::uint64_t traceBytes = 0;       // scene distance, samples, two histories and the near
                                      //   field's samples and two histories (trace extent)
  std::uint64_t upsamplingBytes = 0;  // two output-resolution histories (temporal upsampling)
  std::uint64_t shadowBytes = 0;      // the cloud shadow map and its spare cascade
  std::uint64_t godRayBytes = 0;      // the god-ray occlusion image, mask and light
  std::uint64_t lightningBytes = 0;   // the glow image, the flashes' blocks, the bolts' buffers
  std::uint64_t heroCloudBytes = 0;   // the hero clouds' atlas (setHeroCloudAssets()), its upload
                                      //   buffer until a frame has copied it, their blocks
  std::uint64_t skyLightBytes = 0;    // the sky light's map, its clouds and measures (skyLight)
  std::uint64_t bufferBytes = 0;      // uniforms, work counters, placeholders
  std::uint64_t retiredBytes = 0;     // images a larger prepare() replaced, freed once the
                                      //   frames in flight that may use them have retired
  std::uint64_t totalBytes() const {
    return noiseBytes + weatherBytes + outputBytes + traceBytes + upsamplingBytes + shadowBytes +
           godRayBytes + lightningBytes + heroCloudBytes + skyLightBytes + bufferBytes +
           retiredBytes;
  }
};

enum class Jitter : std::uint32_t {
  None = 0,         // every ray starts at the segment start (banding at low step counts)
  BayerHalton = 1,  // 4x4 Bayer per pixel plus a Halton offset per frame
  // Also moves each frame's rays inside their pixels (Halton 2, 3): frames averaged by the
  // host converge to a supersampled image. The Reference mode's jitter.
  BayerHaltonSubpixel = 2,
};

// How a hero cloud shadows itself: the optical depth towards the sun of a sample in its box
// through its own voxels (Schneider 2023, Nubis³'s voxel-based lighting).
enum class HeroLight : std::uint32_t {
  // The light cone through every density source, as the layer's samples take it (lightSteps
  // samples): Nubis³'s "base". With few steps, hero clouds come out too bright.
  Cone = 0,
  // The light volume: the optical depth swept through each instance's voxels towards the sun at
  // 2-voxel spacing, refreshed when its sun, asset or life changes; a sample takes one lookup,
  // and the cone the rest (the layer, other hero clouds).
  Volume = 1,
  // The straight integral the volume approximates, marched per sample at half a voxel: the
  // Reference's.
  Marched = 2,
};

// What a hero cloud is between its voxels (Schneider 2023, Nubis³'s voxel cloud density).
enum class HeroDetail : std::uint32_t {
  // Its voxels as filtered: density linear in the dimensional profile, smooth over a voxel
  // (what OpenVDB's own renderer shows of the same grid).
  Off = 0,
  // Up-rezzed to half a metre: the profile eroded by a 128^3 noise of wisps (curly alligator)
  // and billows (alligator) as each voxel's detail type asks, read at the level one pixel covers
  // (generated on the GPU, 10 MiB, the first frame that wants it). Follows `detail`: without
  // it, and in the light, the shadow map and the distance queries, the noise's mean erodes.
  Uprezzed = 1,
};

// Plain settings with defaults; ranges are checked by validateSettings() and dispatch().
struct Settings {
  // --- Cloud layer -----------------------------------------------------------------------
  float layerBottomMetres = 1500.0f;      // [0, 20000] altitude of the cloud base
  float layerTopMetres = 4000.0f;         // (layerBottom, 30000] altitude of the tops
  float planetRadiusMetres = 6360000.0f;  // [1e5, 1e8]

  // --- Weather -----------------------------------------------------------------------------
  float coverage = 0.5f;               // [0, 1] 0 clear sky, 0.5 the weather map as is, 1 overcast
  float cloudType = 0.75f;             // [0, 1] 0 stratus, 0.5 stratocumulus, 1 cumulus
  float typeVariation = 0.5f;          // [0, 2] how far the weather map moves the type
  float densityVariation = 0.3f;       // [0, 1] how far the weather map scales the density
  float weatherTileMetres = 50000.0f;  // [1000, 1e7] one weather-map tile covers this square
  float weatherEvolutionPerSecond = 0.0005f;  // [0, 1] rate the procedural weather evolves
  float weatherUpdateSeconds = 1.0f;          // [0, 3600] regenerate the procedural map this often

  // --- Shape ---------------------------------------------------------------------------
  float densityMultiplier = 1.0f;         // [0, 1e6] scales the extinction of all clouds
  float extinctionPerMetre = 0.12f;       // [0, 100] extinction (1/m) at density 1
  float anvilBias = 0.0f;                 // [0, 1] inflates cumulus tops into anvils
  float shapeTileMetres = 6250.0f;        // [100, 1e7] the low-frequency noise repeats this often
  float detailTileMetres = 1250.0f;       // [10, 1e6] the high-frequency noise repeats this often
  float detailErosion = 0.45f;            // [0, 1] how deeply detail noise carves edges
  float detailDistanceMetres = 30000.0f;  // [0, 1e7] no detail erosion beyond this distance
  float curlTileMetres = 12500.0f;        // [100, 1e7] the curl noise repeats this often
  float curlStrengthMetres = 120.0f;      // [0, 10000] swirl of the detail noise at the cloud base

  // --- Wind --------------------------------------------------------------------------------
  glm::vec2 windDirection{1.0f, 0.0f};     // world (x, z), any non-zero length
  float windSpeedMetresPerSecond = 10.0f;  // [0, 500] noise scroll; coverage stays put
  float skewMetres = 500.0f;               // [0, 20000] downwind lean across the layer
  // The lean follows the wind as it turns with height, so a storm's top leans the way the
  // upper wind blows (Schneider 2017: anvils skewed by their own wind).
  float windShearDegrees = 0.0f;  // [-180, 180] the wind's turn from base to top (ccw from above)

  // --- Lighting ----------------------------------------------------------------------------
  float albedo = 0.99f;              // [0, 1] single-scattering albedo
  float phaseForwardG = 0.8f;        // [-1, 1] forward HG lobe (silver lining); clamped 0.99
  float phaseBackwardG = -0.3f;      // [-1, 1] backward HG lobe
  float phaseBackwardWeight = 0.3f;  // [0, 1] blend towards the backward lobe
  float silverIntensity = 0.0f;      // [0, 10] the seeds' silver lining: a sharp forward lobe
                                     //   max()ed with the two, renormalised (0: off)
  float silverSpread = 0.05f;        // [0, 0.99] its width: its HG g is 0.99 - spread
  bool multipleScattering = true;    // octave approximation of multiple scattering
  std::uint32_t multipleScatteringOctaves = 6;  // [1, 8]
  float msExtinctionScale = 0.3f;               // [0, 1] a: extinction factor per octave
  float msContribution = 0.85f;                 // [0, 1] b: energy factor per octave
  float msEccentricityScale = 0.5f;             // [0, 1] c: phase g factor per octave
  float inScatterStrength = 1.0f;               // [0, 1] Nubis dark edges and bases (0: off)
  float inScatterCoreProfile = 0.4f;            // [0.01, 1] the coarse profile (0 at a cloud's
                                                //   edge, 1 inside) from which cloud is lit as
                                                //   core: below it, edges darken
  float ambientOcclusionStrength = 1.0f;        // [0, 1] darkening of ambient inside dense cloud
  float ambientStrength = 1.0f;                 // [0, 100] scales the ambient sky term
  float sunStrength = 1.0f;                     // [0, 100] scales the direct sun term

  // --- Ray-march ---------------------------------------------------------------------------
  std::uint32_t maxViewSteps = 128;        // [1, 16384] samples along a view ray at most (steps
                                           // stretch where they would not reach its end), plus
                                           // 9 near the camera
  float viewStepMetres = 60.0f;            // [0.5, 10000] step length near the camera (within
                                           // twice this, half the distance to it, from 1/16)
  float viewStepGrowth = 0.004f;           // [0, 1] extra step length per metre of distance
  std::uint32_t lightSteps = 6;            // [0, 64] samples towards the sun per cloudy sample
  float lightConeMetres = 1800.0f;         // [1, 100000] reach of the light samples
  float lightConeSpread = 0.25f;           // [0, 2] sideways spread of the cone
  float maxDistanceMetres = 60000.0f;      // [100, 1e7] nothing is marched beyond this
  float transmittanceCutoff = 0.005f;      // [0, 0.5] early exit below this transmittance
  bool cheapSampling = true;               // coarse cheap steps in empty space (Nubis switch)
  float coarseStepFactor = 2.5f;           // [1, 16] coarse step = factor x fine step
  std::uint32_t emptySamplesToCoarse = 6;  // [1, 1000] empty fine samples before going coarse
  bool detail = true;                      // high-frequency erosion
  // Noise level of detail: a sample reads the mip level of the shape and detail noise whose
  // texels are 1/noiseTexelsPerPixel of one output pixel's width there (distance x the pixel's
  // angle), so distant clouds alias less; nearer ones keep level 0. Off: level 0 everywhere,
  // what the Reference does (its rays move inside their pixels instead). The density remaps the
  // noise against the coverage, and the remap of averaged noise is not the average of the
  // remapped noise: fewer texels a pixel flicker less but lose accuracy; 4 (the default) keeps
  // it.
  bool noiseLevelOfDetail = true;
  float noiseTexelsPerPixel = 4.0f;  // [1, 64] level-0 texels a pixel covers where LOD starts
  // Light reuse: of two cloudy view samples in a row, the second takes the first's optical
  // depth towards the sun instead of marching its own (on every other step of the march, the
  // same steps for every ray, so that on a CPU's 8-wide lanes whole groups skip the light
  // samples together). The error is first order in the step; the Reference marches every
  // sample's own.
  bool lightEveryOtherStep = true;
  Jitter jitter = Jitter::BayerHalton;
  bool emptySpaceSkipping = true;                // jump over weather cells without cloud (exact)
  HeroLight heroLight = HeroLight::Volume;       // hero clouds' self-shadowing (HeroLight)
  HeroDetail heroDetail = HeroDetail::Uprezzed;  // hero clouds' detail (HeroDetail)

  // --- Resolution and temporal reconstruction ----------------------------------------------
  // The march runs at traceScale x the output resolution (per axis); each frame it refreshes
  // one pixel in every k x k tile (k * k = updateInterval) and reprojects last frame's result
  // for the rest; a depth-aware upsample produces the output. Where reprojection cannot work
  // (camera cut, resize, big jumps or relighting, the camera moving in or near the layer) the
  // frame falls back to a denser tile of at most 2 x 2, rebuilt from this frame's samples alone.
  float traceScale = 0.5f;            // {1, 0.5, 0.25} trace resolution / output resolution
  std::uint32_t updateInterval = 16;  // {1, 4, 16, 64} frames between refreshes of a pixel
  bool temporalReuse = true;          // reproject history (off: every frame stands alone)
  float temporalFreshWeight = 0.6f;   // [0.05, 1] weight of a fresh sample over its history
  // The same while nothing moves (camera, projection and clouds as last frame: the history is
  // exact, so it can average the rays' noise over more refreshes without lag or smear): the
  // mean of a pixel's rays since the history started (1 / refreshes), down to this.
  float temporalStillFreshWeight = 0.2f;  // [0.05, 1]
  // Temporal upsampling (traceScale < 1 only): the march's rays also move inside their trace
  // pixel from one refresh to the next, and an output-resolution history keeps each output
  // pixel's own samples (up to upsamplingMaxSamples, then a running mean), so a static or
  // slowly turning view converges to full-resolution detail (two own samples per output pixel
  // after 2 x updateInterval / traceScale^2 frames: 128 at High) instead of staying at the
  // trace resolution. Where the history is uncertain it falls back to the trace-resolution
  // reconstruction. Costs two output-resolution history images (8 bytes per pixel each) and a
  // dearer upsample pass, which reprojects them.
  // Sharpest with a still camera and still clouds; when anything moves (the camera, or the
  // clouds' detail with the wind) the own samples are reprojected every frame and clamped to
  // this frame's trace neighbourhood, which keeps less of the detail.
  bool temporalUpsampling = false;
  std::uint32_t upsamplingMaxSamples = 4;  // [1, 15] own samples averaged before the running mean
  // Edge rays (temporal upsampling only): a tile whose trace pixels around ranged from cloud
  // to clear last frame (the rims of clouds, where an output pixel's coverage is what its few
  // own samples get wrong) marches this many more rays this frame, each through another output
  // pixel of its trace pixel, so that output pixels on silhouettes gather own samples up to
  // three times as fast. A second dispatch marches the listed edge tiles' rays side by side,
  // so the cost follows their count.
  std::uint32_t edgeRays = 0;       // [0, 2] more rays per tile on a silhouette
  float historyClampMargin = 0.1f;  // [0, 1] slack of the history clamp (x neighbourhood range)
  // The history is clamped to this frame's fresh neighbourhood only as far as its reprojection
  // is uncertain: fully where the nearest cloud and the far distance reproject this many trace
  // pixels apart (a moving camera near cloud), not at all for a static or turning camera.
  float historyClampSpreadPixels = 1.0f;  // [0.01, 100]
  // Inside the layer or this close to it, a moving camera refreshes the trace at
  // movingInsideUpdateInterval when that is shorter than updateInterval (the cloud all around
  // it changes from frame to frame: 4, 2 x 2 tiles, is 5 dB more accurate flying up into the
  // base than 16, for 4 times the march), and a frame without history is rebuilt by a tent
  // over its rays (reconstruct.comp).
  float insideLayerMarginMetres = 50.0f;         // [0, 5000]; a hero cloud's box's too
  std::uint32_t movingInsideUpdateInterval = 4;  // 1, 4, 16 or 64, as updateInterval
  // Near/far split (Nubis³): while the camera is within this distance of the layer or of a
  // hero cloud's box, the clouds nearer than it are marched apart, every pixel of an image at
  // half the trace's resolution every frame, and laid over the far part, which keeps the sparse
  // refresh and its history. The near part moves most from frame to frame (parallax, flying through
  // it), where reprojected history smears and its clamp leaves blocks; the far part, beyond it,
  // reprojects well. 0: no split, no pass, no image. Turning on or off resets the history.
  float nearFieldMetres = 0.0f;                // [0, 2000]
  float historyResetDistanceMetres = 2000.0f;  // [1, 1e6] camera move in one frame that resets
  float historyResetAngleDegrees = 30.0f;      // [0.1, 180] camera turn in one frame that resets
  float relightResetDegrees = 2.0f;            // [0.01, 180] sun turn in one frame that resets
  float relightResetRatio = 0.2f;              // [0.001, 10] relative change of sun illuminance

  // --- Cloud depth output (Outputs::depth) ---------------------------------------------------
  // false: a host that reads only the radiance output saves the depth output's stores and its
  // memory; the depths are still used inside (haze, reprojection) and the radiance is the same
  // to the bit.
  // Outputs::depth is then null, unless lightningBoltSegments > 0 (the bolts' pass reads it).
  bool depthOutput = true;

  // --- Cloud shadow map (Context::dispatchShadowMap(), Outputs::shadowMap) -----------------
  // A Beer shadow map of the clouds for the host's receivers: square cascades seen along the
  // sun, centred near the camera (below it when it flies above the layer), each
  // shadowCascadeRatio times the side of the one before, snapped to whole texels. Each texel
  // marches its sun ray through the layer with the low-frequency shape, like the light
  // samples. Cascades are remade in turn (the finest every other time); a camera cut, a jump,
  // new settings or a turn of the sun remakes them all at once. A cascade's turn may be spread
  // over shadowFramesPerCascade frames, a slice of its rows per frame, made into a spare image
  // and copied in whole when done (receivers never see a half-made cascade); every slice
  // samples the clouds as they were at the first, so the result is the cascade a single frame
  // would have made then. With more than one frame per cascade, one cascade is in the making
  // at a time (shadowCascadesPerFrame is not used) and a frame that must remake cascades at
  // once abandons it.
  std::uint32_t shadowCascades = 4;          // [0, 4] 0: no shadow map, no pass, no memory
                                             //   (and bases see an unshaded ground)
  std::uint32_t shadowMapResolution = 128;   // [16, 1024] texels per cascade side
  float shadowNearSideMetres = 10000.0f;     // [500, 1e6] side of the finest cascade
  float shadowCascadeRatio = 3.0f;           // [1.5, 8] side of a cascade over the one before
  std::uint32_t shadowSteps = 16;            // [1, 256] samples along each texel's sun ray
  std::uint32_t shadowCascadesPerFrame = 1;  // [1, 4] cascades remade per frame
  std::uint32_t shadowFramesPerCascade = 1;  // [1, 8] frames one cascade's turn is spread over
  // With FrameInputs::terrain: heightfield samples along each texel's sun ray, from where it
  // is at the terrain's lowest altitude to where it clears the highest (at a sun 5 degrees up
  // over 2 km of relief, 23 km of ray: 48 samples are 480 m apart).
  std::uint32_t terrainShadowSteps = 48;  // [1, 1024]
  // With a map made this frame (dispatchShadowMap() before dispatch()), the clouds shadow
  // themselves over kilometres: beyond its light cone (lightConeMetres) a sample's sun is dimmed
  // by the map's optical depth of the clouds from the cone's end on (Schneider 2022), so a
  // cumulus under an anvil or deep in an overcast is darker where kilometres of cloud lie
  // towards the sun. Read where a ray enters cloud and every 4th step after; on in the presets
  // High, Ultra and the Reference (its cost: docs/measurements.md). false: the cone alone (as
  // without a map); a march variant of its own, so a false costs nothing.
  bool cloudShadowsOnClouds = true;

  // --- God rays (Outputs::godRayMask, fxcontracts/god_rays.h)
  // --------------------------------------- dispatch() makes the god-ray mask at a quarter of the
  // render extent: the share of each pixel's way towards the sun on screen that sees it past the
  // clouds and the host's geometry (a radial blur, Mitchell 2007). The radiance output then takes
  // the hidden part of the haze's Mie in-scattering from the sky's pixels (with
  // FrameInputs::aerialPerspective and its scattering coefficients), or adds a glow along the clear
  // paths (without). A sky that cannot hold cloud is not marched and gets none. 0 samples: no mask,
  // no pass, no memory.
  std::uint32_t godRaySamples = 0;   // [0, 128] samples along each texel's way to the sun
  float godRayLength = 0.9f;         // [0.05, 1] fraction of the way the samples cover
  float godRayDecay = 0.97f;         // [0.5, 1] weight of each sample over the one before
  float godRayGlowStrength = 0.05f;  // [0, 10] the fallback's glow (no haze), sr^-1 scale

  // --- Lightning (FrameInputs::lightningFlashes) ---------------------------------------------
  // How many flashes the clouds can glow with at once. 0: no glow code in any pipeline, no
  // buffer; a frame's flashes must then be none.
  std::uint32_t lightningFlashes = 0;  // [0, 16]
  // How many straight segments of lightning bolts (FrameInputs::lightningBolts) the output can
  // draw at once. 0: no bolt pipeline, pass or buffer; a frame's bolts must then be none.
  std::uint32_t lightningBoltSegments = 0;  // [0, 256]

  // --- Weather regions (FrameInputs::weatherRegions) ------------------------------------------
  // How many regions a frame may have. 0: no region code in any pipeline; a frame's regions
  // must then be none. Each one compiled in costs every sample a little (regions or not).
  std::uint32_t weatherRegions = 0;  // [0, 8]
  // Whether a frame's regions may hold a superstorm (one region with WeatherRegion::vortex, so
  // with weatherRegions >= 1). 0: no vortex code in any pipeline.
  std::uint32_t superstorms = 0;  // [0, 1]
  // The history follows the storm's turn (a point's previous place is turned back about the
  // eye by the frame's rotation); off: plain reprojection (camera and wind only), for the
  // benchmark's comparison.
  bool vortexReprojection = true;

  // --- Sky light (Outputs::skyLight, Context::skyLighting()) ---------------------------------
  // The host's sky with the clouds in it, for what the host lights with the sky (its ground's
  // ambient, reflections, an exposure meter): an equirectangular map laid out as
  // FrameInputs::skyView, whose upper half is that sky seen through the clouds marched towards
  // each texel (a quarter of them a frame, lit as the view's clouds are), and its measures.
  // Needs FrameInputs::skyView. false: no pass, no memory.
  bool skyLight = false;
};

// The sky light's map (Outputs::skyLight), texels.
inline constexpr VkExtent2D kSkyLightExtent{64, 32};

// What the sky light's map measures (Context::skyLighting()): RGB radiances in the host's
// units. Lighting a surface facing up with the sky means pi x upperIrradianceOverPi; the
// regions are means by solid angle.
struct SkyLighting {
  bool valid = false;  // the frame made a sky light
  // The upper hemisphere weighted by the cosine to the zenith: a horizontal surface's
  // irradiance / pi.
  glm::vec3 upperIrradianceOverPi{0};
  glm::vec3 zenith{0};   // above 60 degrees of elevation
  glm::vec3 horizon{0};  // from the horizon up to 10 degrees
  glm::vec3 lower{0};    // the lower hemisphere
  // FrameInputs::skyView's alone, as upperIrradianceOverPi: the light the clouds took or gave.
  glm::vec3 clearIrradianceOverPi{0};
  // For an exposure meter at the camera: the clouds' transmittance of the sun there and the
  // share of the ground around it in the sun (the mean over the shadow map's finest cascade;
  // both 1 without a map), the altitude (m) the map's upper half was seen from (the camera's,
  // or under the layer for a camera in or above it), and the layer's top (m), above which the
  // host's clear sky holds.
  float sunTransmittanceAtCamera = 1.0f;
  float sunlitShareAround = 1.0f;
  float seenFromAltitudeMetres = 0.0f;
  float coverTopMetres = 0.0f;
};

// Quality presets, cheapest first; Reference is referenceSettings().
enum class Quality : std::uint32_t { Low, Medium, High, Ultra, Reference };
const char* qualityName(Quality quality);
// Parses a qualityName() case-insensitively; false (and *quality untouched) when unknown.
bool parseQuality(std::string_view name, Quality* quality);
// Pure function: `base` with the cost knobs of `quality` (look settings such as coverage,
// lighting and wind are kept).
Settings settingsFor(Quality quality, const Settings& base = {});

// Whether temporal upsampling is in effect: Settings::temporalUpsampling at a traceScale < 1.
bool upsamplesTemporally(const Settings& settings);

// Empty when every field is in range, else "Settings.<field> = <value>: <reason>" for the
// first field at fault.
std::string validateSettings(const Settings& settings);

// The converged reference mode of the same shader: full resolution, no temporal reuse, short
// steps, many light samples, no coarse sampling or empty-space skipping, and no early exit
// worth mentioning. Ground truth for accuracy-versus-cost.
Settings referenceSettings(const Settings& base);

// A place on the ground whose weather differs from the surrounding weather the Settings hold
// (Schneider 2022's regional influence): a storm front over the mountains, fair skies over the
// plains. The region's core is a rectangle (half sides 0: a point) grown by a rounding radius;
// within it the region's look holds, and it eases (smoothstep) into the surrounding weather
// over the blend distance beyond. Regions apply in the order given, each over what the ones
// before it made. A region sets the look of the clouds over it (coverage, type, density,
// anvils); the wind, skew, shear and erosion are the Settings' everywhere (the noise moves as
// one field). clouds/weather.h's withWeather() sets a region's look from a WeatherState.
struct WeatherRegion {
  glm::dvec2 centreMetres{0.0};     // world (x, z), finite
  glm::vec2 halfSidesMetres{0.0f};  // [0, 1e7] the core rectangle's half sides along its axes
  float headingDegrees = 0.0f;      // finite: the rectangle's first axis, turned from world +x
                                    //   towards -z (counter-clockwise seen from above)
  float radiusMetres = 0.0f;        // [0, 1e7] the core: the rectangle grown by this
  float blendMetres = 10000.0f;     // [100, 1e7] from the look at the core to the surroundings'
  float coverage = 0.5f;            // Settings::coverage inside
  float cloudType = 0.75f;          // Settings::cloudType inside
  float densityMultiplier = 1.0f;   // Settings::densityMultiplier inside
  float anvilBias = 0.0f;           // Settings::anvilBias inside

  // A superstorm (Schneider 2022, seed 001: the "M.D.R. vortex field"): the region's cloud
  // field turns about its centre, fastest at the eye wall, and its look is an eye without cloud
  // ringed by a wall of cumulonimbus (cloud type 1, coverage 1) with spiral rain bands of the
  // region's coverage beyond. A vortex region is a disc (halfSidesMetres 0): the eye wall and
  // the bands lie within radiusMetres, and the turn fades with the region over blendMetres.
  // The noise is read turned back by the angle the field has turned through; two reads half a
  // period apart, cross-faded, keep the differential turn from winding the noise without bound
  // (a flow map's two phases). At most one per frame, with Settings::superstorms.
  struct Vortex {
    float eyeRadiusMetres = 0.0f;            // [0, 1e6] 0: no vortex
    float eyeWallMetres = 4000.0f;           // [100, 1e6] the wall's width beyond the eye
    float wallSpeedMetresPerSecond = 30.0f;  // [-200, 200] the cloud's speed at the wall's
                                             //   middle, counter-clockwise seen from above
                                             //   (negative: clockwise)
    float spiralArms = 3.0f;                 // [0, 8] rain bands (0: a plain ring)
    bool operator==(const Vortex&) const = default;
  };
  Vortex vortex;

  bool operator==(const WeatherRegion&) const = default;
};
inline constexpr std::uint32_t kMaxWeatherRegions = 8;  // FrameInputs::weatherRegions per frame

// The weather over a world column as the march reads it from the procedural weather map (not
// from a painted one), under `settings` and the frame's weather regions: for hosts that place
// things by the weather (storm cells where cumulonimbus is dense, ...). A pure function of its
// arguments; it evaluates the map's function where the march filters its 512^2 texels, so it
// is as exact as a texel.
struct WeatherColumn {
  float coverage = 0.0f;  // [0, 1] the sky this column can fill (its coverage applied)
  float type = 0.0f;      // [0, 1] 0 stratus, 0.5 stratocumulus, 1 cumulus and cumulonimbus
  float density = 0.0f;   // [0, 1] the map's density scale
  float densityMultiplier = 0.0f;  // the column's (Settings::densityMultiplier, or a region's)
};
WeatherColumn proceduralWeatherAt(const Settings& settings, std::uint32_t noiseSeed,
                                  glm::dvec2 xzMetres, double timeSeconds,
                                  std::span<const WeatherRegion> regions = {});

// A lightning flash the clouds glow with this frame (Nubis Evolved's glow term): the cloud
// within `radiusMetres` of it glows with `radiance` times pow(1 - d / radius, 12) at distance
// d, less where the cloud is dense (the light cannot get out). The host animates `radiance`
// over a flash's return strokes; the module keeps nothing of it from frame to frame.
struct LightningFlash {
  glm::dvec3 positionMetres{0.0};  // world, where the charge glows (inside the cloud)
  float radiusMetres = 3000.0f;    // > 0, finite
  glm::vec3 radiance{0.0f};        // >= 0, finite: in the host's radiometric units
};

// A straight piece of a lightning bolt (a ground discharge's channel and its branches, as many
// pieces as the host cuts it into). The radiance output shows it as a line `widthMetres` wide,
// drawn at full resolution over everything it is in front of: hidden by the host's geometry
// nearer than it, behind the clouds as much as they let through when they are nearer, and
// hazed like the clouds (FrameInputs::aerialPerspective). A line thinner than a pixel keeps its
// energy: its radiance times the share of the pixel it covers. Like the flashes, nothing of a
// bolt is kept from frame to frame.
struct LightningBoltSegment {
  glm::dvec3 fromMetres{0.0};  // world, finite
  glm::dvec3 toMetres{0.0};    // world, finite
  glm::vec3 radiance{0.0f};    // >= 0, finite: the channel's, in the host's radiometric units
  float widthMetres = 2.0f;    // > 0, finite: the glowing channel's width
};

struct NvdfVolume;  // clouds/nvdf.h

// A hero cloud placed in the world this frame (Nubis³'s voxel clouds): one of the assets the
// host gave Context::setHeroCloudAssets(), its frame's origin at `positionMetres`, scaled and
// turned about the vertical. The march draws it with the layer, by depth, in the same image.
// Its life changes it over minutes with the same voxels (clouds/hero_cloud_life.h has a
// timeline): growing, its top rises from its base and its edge swells from its cores out;
// dissipating, it thins from its edge in and fades. Both change it continuously, so a host
// that moves them a little each frame never makes it pop.
struct HeroCloud {
  std::uint32_t asset = 0;         // index into the last setHeroCloudAssets() list
  glm::dvec3 positionMetres{0.0};  // world, finite
  float scale = 1.0f;              // [0.01, 100]: world metres per metre of the asset
  float yawRadians = 0.0f;         // finite: a turn about +y, taking +z towards +x
  float growth = 1.0f;             // [0, 1]: 0 not yet there, 1 as authored
  float dissipation = 0.0f;        // [0, 1]: 0 as authored, 1 gone
};
inline constexpr std::uint32_t kMaxHeroClouds = 8;  // FrameInputs::heroClouds per frame

struct FrameInputs {
  VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
  VkExtent2D renderExtent{0, 0};  // <= CreateInfo::maxRenderExtent; size of depth and outputs

  // The host's depth buffer (optional). Must be in `depthLayout` (a read-only or GENERAL
  // layout) with its writes made visible to compute-shader reads before these commands.
  // Clouds behind geometry are not marched; clouds in front cover it.
  VkImageView depthView = VK_NULL_HANDLE;
  VkImageLayout depthLayout = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;

  // Camera: world->view and view->clip as the host renders with them, without TAA jitter
  // (only the rotation of `view` is used; the position comes from cameraPosition, in double
  // precision). This frame's only: the module remembers the camera of its history.
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::dvec3 cameraPosition{0.0, 0.0, 0.0};  // metres; y = altitude above sea level

  // Lighting in the host's radiometric units (see the conventions above).
  glm::vec3 sunDirection{0.0f, 1.0f, 0.0f};  // unit, towards the sun
  glm::vec3 sunIlluminance{10.0f};           // illuminance of the sun at the clouds, RGB
  glm::vec3 ambientTop{1.0f};                // sky radiance lighting cloud tops, RGB per steradian
  glm::vec3 ambientBottom{0.5f};             // radiance lighting cloud bases, RGB per steradian
                                             //   (with groundAlbedo: the horizon's radiance)
  // Optional sky radiance as an equirectangular image (u = azimuth, v = 0 at the zenith),
  // sampled in `skyLayout`; when set it replaces ambientTop/ambientBottom (ambientBottom by
  // the mean of the band up to 10 degrees above the horizon).
  VkImageView skyView = VK_NULL_HANDLE;
  VkImageLayout skyLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  // Optional: the ground's Lambertian albedo, [0, 1] per channel. With it cloud bases are lit
  // from below by the ground, as they are outdoors: the ground's radiance, albedo / pi x (the
  // sun's illuminance x the sine of its elevation x the share of the ground out of the clouds'
  // shadow + pi x ambientTop), over the lower hemisphere bar its 10 degrees nearest the
  // horizon, which keep the horizon's radiance (ambientBottom). The ground's sunlit share is
  // the mean sun transmittance of the shadow map's finest cascade when dispatchShadowMap() ran
  // this frame, else 1. Approximations: the sun on the ground is sunIlluminance (the sun at the
  // clouds), the sky's irradiance pi x ambientTop; ambientStrength scales the result with the
  // rest of the ambient. Without groundAlbedo ambientBottom alone lights the bases.
  std::optional<glm::vec3> groundAlbedo;

  // Optional aerial perspective: the haze between the camera and every distance, as a 3D
  // volume laid out as fxcontracts/aerial_perspective.glsl says (the atmosphere module's
  // Outputs::aerialPerspective). With it the clouds' radiance output is hazed at their
  // transmittance-weighted depth, rgb * T_air + L_air * (1 - T_clouds), the way the host's
  // geometry is hazed by the same volume; the transmittance output stays the clouds' own.
  struct AerialPerspective {
    VkImageView view = VK_NULL_HANDLE;  // 3D; none: the clouds are not hazed
    VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;  // sampled in this layout
    std::uint32_t slices = 0;                                         // its depth, >= 1 with a view
    float rangeMetres = 0.0f;       // the distance of its last slice, > 0 with a view
    glm::vec3 radianceScale{1.0f};  // multiplies its rgb (the atmosphere's: the sun's
                                    //   illuminance at the top of the atmosphere), >= 0
    // The air's scattering at the ground (per metre) and Mie's asymmetry: god rays take the
    // Mie share of the haze (fxcontracts/god_rays.h). All 0: the haze gets no god rays.
    glm::vec3 rayleighScatteringPerMetre{0.0f};  // >= 0
    glm::vec3 mieScatteringPerMetre{0.0f};       // >= 0
    float miePhaseG = 0.8f;                      // (-1, 1)
  };
  AerialPerspective aerialPerspective;

  // Optional terrain (the host's ground as a heightfield): with it each shadow-map texel also
  // holds where the terrain hides the sun from its ray (the "terrain shadow" pass, in
  // dispatchShadowMap()), so clouds in a mountain's shadow lose their direct sun (dispatch())
  // and a host can shadow its terrain on itself with the same lookup (fxcontracts/cloud_shadow.h).
  // Needs the shadow map: Settings::shadowCascades > 0 and dispatchShadowMap() every frame
  // before dispatch(). Outside the heightfield there is no terrain.
  struct Terrain {
    // 2D, one channel: altitude (m) above sea level, sampled with linear filtering in
    // `heightLayout` (R16_SFLOAT always filters linearly; R32_SFLOAT where the device says).
    VkImageView heightView = VK_NULL_HANDLE;  // none: no terrain
    VkImageLayout heightLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    glm::dvec2 originMetres{0.0};  // world (x, z) of the image's (u, v) = (0, 0) corner
    glm::dvec2 sizeMetres{0.0};    // world extent along x (u) and z (v), > 0
    // The lowest and highest altitude in the image (m): bounds of the walk along each ray.
    float minAltitudeMetres = 0.0f;
    float maxAltitudeMetres = 0.0f;
  };
  Terrain terrain;

  // Optional painted weather map (R coverage, G type, B density; any size, sampled with
  // bilinear filtering in `weatherLayout`) replacing the procedural one.
  VkImageView weatherView = VK_NULL_HANDLE;
  VkImageLayout weatherLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  // Optional second painting the map is blended towards (mix(weatherView, weatherBlendView,
  // weatherBlend), weatherBlend in [0, 1]; needs weatherView). A host easing weatherBlend from 0
  // to 1 over seconds, then passing the second painting as weatherView alone, changes the map
  // without losing the temporal history; swapping weatherView at once drops it.
  VkImageView weatherBlendView = VK_NULL_HANDLE;
  VkImageLayout weatherBlendLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  float weatherBlend = 0.0f;
  // This frame's weather regions, at most kMaxWeatherRegions (the span's memory need only last
  // through the call that takes these inputs). A region whose look eases over seconds, or that
  // the camera flies into, keeps the temporal history; one that appears, vanishes or jumps
  // drops it. None: the surrounding weather everywhere, and the march reads no region.
  std::span<const WeatherRegion> weatherRegions;

  // This frame's lightning flashes, at most Settings::lightningFlashes (the span's memory need
  // only last through the call that takes these inputs).
  std::span<const LightningFlash> lightningFlashes;
  // This frame's lightning bolts, at most Settings::lightningBoltSegments pieces (likewise).
  std::span<const LightningBoltSegment> lightningBolts;
  // This frame's hero clouds, at most kMaxHeroClouds, of the assets setHeroCloudAssets() gave
  // (likewise). None: the march is the one without hero clouds, which reads nothing of them.
  std::span<const HeroCloud> heroClouds;

  double timeSeconds = 0.0;  // >= 0; drives wind and weather evolution
  // Where the wind has carried the clouds' noise by now (x, z metres, finite). None: timeSeconds
  // x the settings' wind, which moves the noise by kilometres when a long-running host changes
  // the wind; a host whose wind changes passes the integral of its wind instead
  // (clouds/weather.h: WeatherTimeline::windDisplacementAt).
  std::optional<glm::dvec2> windDisplacementMetres;
  // The host's frame number, increasing by one per frame: picks the per-frame slot
  // (frameIndex % maxFramesInFlight) and tells when replaced images may be freed.
  std::uint64_t frameIndex = 0;
  bool reset = false;  // camera cut: drop temporal history
};

struct OutputImage {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
};

// Where the cascades of the cloud shadow map lie, relative to the camera of the last
// dispatchShadowMap(); std140-compatible (13 vec4s), so a host copies it into its own uniform
// block. The lookup, as GLSL and C++: fxcontracts/cloud_shadow.h (CloudShadowParameters), in short:
// for a camera-relative position p (m) and cascade c, with U, V, L = cascade[3c .. 3c+2].xyz,
//   uv = (dot(U, p) - cascade[3c].w, dot(V, p) - cascade[3c+1].w) * cascade[3c+2].w
// is in [0, 1]^2 inside the cascade; its texel t (at atlas uv ((c + uv.x) / cascades, uv.y))
// gives the optical depth t.r * clamp((t.g - h) / max(t.g - t.b, 1), 0, 1) above the altitude
// h = info.z + p.y, and the transmittance is exp(-depth). Use the finest cascade that holds p.
struct ShadowMapParameters {
  glm::vec4 cascade[12]{};  // per cascade: (U, u0), (V, v0), (L, 1 / side)
  glm::vec4 info{0.0f};     // cascades (0: no shadow), texels per side, camera altitude (m),
                            //   blend band (fraction of a side)
};

// After dispatch() the outputs are in VK_IMAGE_LAYOUT_GENERAL with their writes visible to
// compute- and fragment-shader reads. The images may be larger than the last dispatch's
// renderExtent (they are sized by prepare()); only `extent` from their origin is valid. A
// prepare() that grows them returns new images: read outputs() again after it.
struct Outputs {
  // RGBA16F: rgb in-scattered radiance towards the camera (premultiplied), a transmittance.
  // Composite: colour = max(scene * a + rgb, 0). With god rays rgb also holds their light for
  // the sky's pixels (fxcontracts/god_rays.h), negative where the haze in the clouds' shadow loses
  // it.
  OutputImage radiance;
  // RG32F: r distance (m) to the first cloud along the pixel's ray, g transmittance-weighted
  // mean distance (m) of the cloud (for haze blending and reprojection); 0 where no cloud.
  // Null without Settings::depthOutput (and bolts).
  OutputImage depth;
  VkExtent2D extent{0, 0};
  // The cloud shadow map (Settings::shadowCascades > 0; else null): RGBA16F, cascades side by
  // side (shadowMapResolution x cascades wide, shadowMapResolution high), in GENERAL with the
  // writes of the last dispatchShadowMap() visible to compute- and fragment-shader reads.
  // Texel: optical depth of its sun ray, altitude (m) of its highest and lowest cloud, and the
  // altitude below which the terrain hides the sun (FrameInputs::terrain; without it, far below).
  OutputImage shadowMap;
  ShadowMapParameters shadowParameters;  // info.x = 0 while there is no map
  // The god-ray mask (Settings::godRaySamples > 0; else null): R32F at godRayParameters'
  // extent (a quarter of the render extent per axis, rounded up), in GENERAL with the writes of
  // the last dispatch() visible to compute- and fragment-shader reads; meaning and use:
  // fxcontracts/god_rays.h. Its parameters: sun (xy the sun's position in the mask's uv, z the
  // fade, w the samples), blur (x length, y decay, zw the mask's extent).
  OutputImage godRayMask;
  glm::vec4 godRaySun{0.0f};
  glm::vec4 godRayBlur{0.0f};
  // The sky light (Settings::skyLight; else null): RGBA16F, kSkyLightExtent, laid out as
  // FrameInputs::skyView, in GENERAL with the writes of the last dispatch() visible to compute- and
  // fragment-shader reads.
  OutputImage skyLight;
};

namespace detail {
struct ContextAccess;  // the module's own tests and tools reach internals through it
}

class Context {
 public:
  class Impl;  // the implementation: opaque to hosts

  // Creates the pipelines and images every frame needs whatever the settings (noise, weather
  // map, composite); prepare() adds what depends on the settings and the render extent.
  // Returns nullptr and fills `error` when the device lacks something or creation fails;
  // whatever was created by then is destroyed.
  static std::unique_ptr<Context> create(const CreateInfo& info, Error* error);
  // The host must ensure the GPU no longer uses the module's objects (e.g. after
  // vkDeviceWaitIdle or its frame fences).
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Makes `settings` at `renderExtent` ready for dispatch(): the pipeline variants they select
  // and images at least that large (output, trace and history images; the output-resolution
  // history only when the settings upsample temporally). Call it outside command recording:
  // at load, on a resize, when the settings change. It may create pipelines and allocate
  // memory and is cheap when nothing is new (no Vulkan call). Images only grow; images it
  // replaces are freed by a later dispatch() once the frames that may use them have retired.
  // Growing drops the temporal history. Returns false and fills `error` (InvalidSettings,
  // InvalidInputs for an extent beyond maxRenderExtent, OutOfMemory, VulkanFailure).
  bool prepare(const Settings& settings, VkExtent2D renderExtent, Error* error);
  // Whether dispatch() can run `settings` at `renderExtent` without a prepare().
  bool prepared(const Settings& settings, VkExtent2D renderExtent) const;

  // The hero clouds' assets (clouds/nvdf.h; each valid, see validateNvdf()) that
  // FrameInputs::heroClouds place, replacing any given before; an empty list frees them. Call
  // it outside command recording, when the GPU no longer uses the module's objects (as for
  // destruction): it allocates their atlas (memoryUsage().heroCloudBytes), and the next frame
  // uploads it. The next prepare() makes the march that draws them. Returns false and fills
  // `error` (InvalidInputs naming the asset, OutOfMemory, VulkanFailure).
  bool setHeroCloudAssets(std::span<const NvdfVolume* const> assets, Error* error);

  // Records this frame's work (its first frame also records the noise generation). Creates
  // and allocates nothing. Returns false and fills `error` (InvalidInputs, InvalidSettings,
  // NotPrepared), naming the field; nothing is recorded then. After this frame's
  // dispatchShadowMap() it samples Outputs::shadowMap too (the terrain's shadow, the clouds' own
  // beyond the light cone, the ground's shade): a host that takes the map out of GENERAL in between
  // returns it there with its transition visible to compute-shader sampled reads.
  bool dispatch(const FrameInputs& inputs, const Settings& settings, Error* error);

  // Records this frame's cloud shadow map (Settings::shadowCascades > 0; with 0 it records
  // nothing and succeeds): the cascades due this frame, with the weather map (and, on the
  // module's first frame, the noise) they need. Reads the camera, sun, time, weather and frame
  // fields of `inputs` (not its depth, extent or projection). Call it before the host's passes
  // that read Outputs::shadowMap and, in a frame that also has dispatch(), before it with the
  // same frameIndex. Creates and allocates nothing. Fails like dispatch().
  bool dispatchShadowMap(const FrameInputs& inputs, const Settings& settings, Error* error);

  // Applies the last dispatch's clouds over `color` (format CreateInfo::compositeColorFormat,
  // STORAGE usage, in VK_IMAGE_LAYOUT_GENERAL, writes visible to compute shaders):
  // color = color * transmittance + radiance, written by a compute shader (synchronise the
  // colour's next use from VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT). Records into
  // `commandBuffer`; `extent` must be the last dispatch's renderExtent.
  bool composite(VkCommandBuffer commandBuffer, VkImageView color, VkExtent2D extent, Error* error);

  Outputs outputs() const;
  FrameReport lastFrameReport() const;
  MemoryUsage memoryUsage() const;
  // The counters of frame `frameIndex`, which must have completed on the GPU and be one of
  // the last maxFramesInFlight frames; zeros unless CreateInfo::workCounters.
  WorkCounters workCounters(std::uint64_t frameIndex) const;
  // The pass times of frame `frameIndex` (same conditions); empty unless
  // CreateInfo::passTimings and the device has compute timestamps.
  std::vector<PassTiming> passTimings(std::uint64_t frameIndex) const;
  // The sky light's measures of frame `frameIndex` (same conditions); valid only when that
  // frame made a sky light (Settings::skyLight).
  SkyLighting skyLighting(std::uint64_t frameIndex) const;

 private:
  friend struct detail::ContextAccess;
  explicit Context(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace clouds
