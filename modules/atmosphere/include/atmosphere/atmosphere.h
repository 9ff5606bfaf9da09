#pragma once
// atmosphere: a physically based sky and aerial perspective (Hillaire 2020, "A Scalable and
// Production Ready Sky and Atmosphere Rendering Technique") as a drop-in Vulkan module, shaped
// like the clouds module:
//   1. atmosphere::Context::create(CreateInfo)            once, with the host's device;
//   2. context->prepare(Parameters, Settings, extent)     outside command recording, when the
//      atmosphere, its quality or the render size change (cheap when nothing is new);
//   3. context->dispatch(FrameInputs, ...)                every frame: records the LUTs that
//      depend only on the parameters when they changed (transmittance, multiple scattering),
//      then the sky-view LUT, the aerial-perspective froxels and the sky-radiance map;
//   4. context->render(...)                               the sky and the sun's disc where the
//      host's depth is far, the aerial perspective over its geometry, in place on its colour
//      (a compute pass); or context->drawSky(...) inside the host's scene pass after its
//      geometry (only the sky's pixels are shaded; the host hazes its geometry itself);
//      context->outputs()                                the LUTs, froxels and sky map for
//      other effects (clouds hazed and lit by the sky) to read.
// Never submits, waits or presents; records only into the host's command buffer.
//
// Conventions: metres; Y up; the planet's centre straight below the camera, its surface at
// y = 0 (the host's world is a flat map with y = altitude above sea level, like the clouds');
// the sun direction points towards the sun. Light is in the host's radiometric units: the
// sun's illuminance at the top of the atmosphere, and radiances per steradian in the same unit
// (e.g. kilolux and kcd/m^2). Reversed-Z depth or not per CreateInfo.
//
// Requirements: Vulkan 1.3 with synchronization2 and shaderStorageImageExtendedFormats; nothing
// optional (VK_EXT_debug_utils only with CreateInfo::debugUtils). A Context is used from one
// thread at a time. No call throws: errors come back as an Error with a code.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace atmosphere {

enum class ErrorCode : std::uint32_t {
  None = 0,
  InvalidCreateInfo,  // a CreateInfo field is missing or out of range
  MissingFunction,    // the proc-addr functions lack an entry point the module needs
  UnsupportedDevice,  // the device lacks a format feature the module needs
  OutOfMemory,        // a Vulkan allocation failed (host, device or descriptor-pool memory)
  VulkanFailure,      // another Vulkan call failed (the message names it and its VkResult)
  InvalidParameters,  // a Parameters field is out of range (validateParameters())
  InvalidSettings,    // a Settings field is out of range (validateSettings())
  InvalidInputs,      // a FrameInputs field, or a render() argument, is invalid
  NotPrepared,        // dispatch() needs prepare() with these settings or this extent first
};
const char* errorCodeName(ErrorCode code);

struct Error {
  ErrorCode code = ErrorCode::None;
  std::string message;
};

// The atmosphere itself. Defaults: Earth (Hillaire 2020's values, after Bruneton 2017).
struct Parameters {
  float bottomRadiusMetres = 6360e3f;  // [1e5, 1e8] the planet (the clouds use the same)
  float topRadiusMetres = 6460e3f;     // (bottom, bottom + 1e6] the top of the atmosphere
  glm::vec3 rayleighScatteringPerMetre{5.802e-6f, 13.558e-6f, 33.1e-6f};  // [0, 1e-3] at the ground
  float rayleighScaleHeightMetres = 8000.0f;                              // [10, 1e6]
  glm::vec3 mieScatteringPerMetre{3.996e-6f};                             // [0, 1e-3]
  glm::vec3 mieExtinctionPerMetre{4.40e-6f};  // [mie scattering, 1e-3]: scattering + absorption
  float mieScaleHeightMetres = 1200.0f;       // [10, 1e6]
  float miePhaseG = 0.8f;                     // [-0.99, 0.99] Cornette-Shanks asymmetry
  glm::vec3 ozoneAbsorptionPerMetre{0.650e-6f, 1.881e-6f, 0.085e-6f};  // [0, 1e-3] at the peak
  float ozoneCentreMetres = 25000.0f;         // [0, 1e6] altitude of the ozone tent's peak
  float ozoneHalfWidthMetres = 15000.0f;      // [1, 1e6]: 10 to 40 km on Earth
  glm::vec3 groundAlbedo{0.3f};               // [0, 1] Lambertian, for light bounced off the ground
  float sunAngularRadiusRadians = 0.004675f;  // [1e-4, 0.2] the sun's disc (0.27 degrees)
};
// Empty when every field is in range, else "Parameters.<field> = <value>: <reason>".
std::string validateParameters(const Parameters& parameters);

// What it costs: LUT sizes and samples per integral.
struct Settings {
  std::uint32_t transmittanceWidth = 256;       // [4, 4096]
  std::uint32_t transmittanceHeight = 64;       // [4, 4096]
  std::uint32_t transmittanceSamples = 40;      // [1, 4096] along each texel's path to the top
  std::uint32_t multiScatteringSize = 32;       // [4, 1024] square
  std::uint32_t multiScatteringDirections = 8;  // [1, 64] per axis: this squared directions
  std::uint32_t multiScatteringSamples = 20;    // [1, 4096] along each direction
  std::uint32_t skyViewWidth = 192;             // [4, 4096]
  std::uint32_t skyViewHeight = 108;            // [4, 4096]
  std::uint32_t skyViewSamples = 30;            // [1, 4096] along each view ray
  // [0, 0.1] the sky-view LUT is kept until the camera's altitude moved more than this fraction
  // of the altitude it was built at, or the sun's elevation moved at all (0: whenever the
  // altitude changed). 0.005 keeps the sky within 0.75% of a rebuilt one's (tested from 100 m
  // to 10 km, sun at 3 and 30 degrees).
  float skyViewAltitudeTolerance = 0.005f;
  std::uint32_t aerialPerspectiveWidth = 32;           // [1, 512] froxels across the screen
  std::uint32_t aerialPerspectiveHeight = 32;          // [1, 512]
  std::uint32_t aerialPerspectiveSlices = 32;          // [1, 512] along the view
  std::uint32_t aerialPerspectiveSamplesPerSlice = 2;  // [1, 64]
  float aerialPerspectiveRangeMetres = 100000.0f;      // [100, 1e7] the last slice's reach
};
// Empty when every field is in range, else "Settings.<field> = <value>: <reason>".
std::string validateSettings(const Settings& settings);

// Quality presets, cheapest first; Reference is the converged ground truth of the benchmark.
enum class Quality : std::uint32_t { Low, Medium, High, Reference };
const char* qualityName(Quality quality);
bool parseQuality(std::string_view name, Quality* quality);  // case-insensitive
Settings settingsFor(Quality quality);

struct CreateInfo {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
  PFN_vkGetDeviceProcAddr getDeviceProcAddr = nullptr;
  bool debugUtils = false;  // the host enabled VK_EXT_debug_utils: names and labels
  // The colour image render() writes: RGBA16F with STORAGE usage.
  VkFormat colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  VkFormat depthFormat = VK_FORMAT_D32_SFLOAT;  // of the depth views render() reads
  VkExtent2D maxRenderExtent{1920, 1080};       // a bound, [1, 16384] per side
  std::uint32_t maxFramesInFlight = 2;          // [1, 8], as the clouds module's
  bool reversedZ = true;
  // The colour format of the host's scene pass drawSky() draws in (dynamic rendering, with a
  // depth attachment of depthFormat); VK_FORMAT_UNDEFINED: no drawSky(), and no graphics
  // pipeline is made (then the device needs no dynamicRendering).
  VkFormat skyPassColorFormat = VK_FORMAT_UNDEFINED;
  bool passTimings = false;  // timestamps per pass for passTimings()
};

struct FrameInputs {
  VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
  VkExtent2D renderExtent{0, 0};
  // The camera as the host renders with it (only the rotation of `view` is used).
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::dvec3 cameraPosition{0.0};  // metres; y = altitude above the ground
  glm::vec3 sunDirection{0.0f, 1.0f, 0.0f};
  glm::vec3 sunIlluminance{1.0f};  // at the top of the atmosphere, host units, >= 0
  std::uint64_t frameIndex = 0;    // increases by one a frame; picks per-frame slots

  // Optional shadow of the sun in the air (light shafts): a cloud shadow map laid out and read
  // as fxcontracts/cloud_shadow.h says (the clouds module's Outputs::shadowMap and
  // shadowParameters, relative to this frame's camera). With it the aerial perspective's single
  // scattering of the sun is taken where the map says the sun is hidden (by cloud, and by terrain
  // when the map has it), so shadowed air scatters less; its multiple scattering is left as it is.
  struct CloudShadow {
    VkImageView view = VK_NULL_HANDLE;               // none: the air is lit everywhere
    VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL;  // sampled (linear, clamped) in this layout
    glm::vec4 parameters[13]{};  // CloudShadowParameters, field for field (std140)
  };
  CloudShadow cloudShadow;
};

struct OutputImage {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent3D extent{0, 0, 0};
};

// After dispatch() every output is in VK_IMAGE_LAYOUT_GENERAL (they are storage images the
// module writes every frame), its writes visible to compute and fragment shaders' sampled
// reads; all RGBA16F, to be sampled with linear filtering, clamped to edges. Hosts read them
// and leave them in GENERAL; the module owns them.
struct Outputs {
  OutputImage transmittance;       // the parameterisation of atmosphere_model.h
  OutputImage multipleScattering;  // ditto
  // Ditto, for this frame's sun and its camera altitude (within skyViewAltitudeTolerance); unit
  // sun.
  OutputImage skyView;
  // The aerial perspective, laid out as fxcontracts/aerial_perspective.glsl says (read it with that
  // header's aerialPerspectiveAt()): 3D, x and y this frame's screen (its view and
  // projection), slice s (texel centre) at aerialPerspectiveRangeMetres * ((s + 0.5) /
  // slices)^2 along each pixel's ray; rgb the radiance the air in front scatters towards the
  // camera for a sun of unit illuminance (multiply by sunIlluminance), a the transmittance
  // (mean of the channels).
  OutputImage aerialPerspective;
  float aerialPerspectiveRangeMetres = 0.0f;  // of the prepared settings
  // The sky's radiance around the camera in host units, equirectangular (64 x 32): u the
  // azimuth from +X towards +Z, v = 0 at the zenith, 0.5 at the horizon, 1 at the nadir (the
  // clouds module's FrameInputs::skyView convention).
  OutputImage environment;
};

// What the sky measured, read back after a frame completed (host units, means by solid angle).
struct SkyLighting {
  glm::vec3 meanUpper{0.0f};        // the upper hemisphere's mean radiance
  float meanUpperLuminance = 0.0f;  // its luminance (Rec. 709 weights): what a light meter reads
  glm::vec3 zenith{0.0f};           // within 30 degrees of the zenith
  glm::vec3 horizon{0.0f};          // the band up to 10 degrees above the horizon
  glm::vec3 lower{0.0f};            // the lower hemisphere
  bool valid = false;               // false until that frame completed
};

struct PassTiming {
  const char* name = "";  // "transmittance", "multiple scattering" (when the parameters
                          // changed), "sky view", "aerial perspective", "environment",
                          // "render"; static storage
  double milliseconds = 0.0;
};

struct MemoryUsage {
  std::uint64_t lutBytes = 0;     // transmittance, multiple-scattering and sky-view LUTs
  std::uint64_t volumeBytes = 0;  // the aerial-perspective froxels
  std::uint64_t otherBytes = 0;   // the sky map, uniforms, readbacks, placeholders
  std::uint64_t totalBytes() const { return lutBytes + volumeBytes + otherBytes; }
};

namespace detail {
struct ContextAccess;
}

class Context {
 public:
  class Impl;

  static std::unique_ptr<Context> create(const CreateInfo& info, Error* error);
  ~Context();  // the GPU must be done with the module's objects
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Pipelines and images for these parameters, settings and render size; marks the LUTs that
  // depend only on the parameters for rebuilding when the parameters changed. Outside command
  // recording; no Vulkan call when nothing is new.
  bool prepare(const Parameters& parameters, const Settings& settings, VkExtent2D renderExtent,
               Error* error);
  bool prepared(const Parameters& parameters, const Settings& settings,
                VkExtent2D renderExtent) const;

  // Records this frame's LUTs and froxels. Creates and allocates nothing.
  bool dispatch(const FrameInputs& inputs, const Parameters& parameters, const Settings& settings,
                Error* error);

  // The sky and the aerial perspective over `color` (CreateInfo::colorFormat, STORAGE usage,
  // GENERAL, its writes visible to compute shaders), in place, after dispatch() this frame:
  // where `depth` (CreateInfo::depthFormat, in `depthLayout`, written before) is the far plane
  // the sky and the sun's disc, elsewhere colour * transmittance + in-scattering at the depth's
  // distance. Without a depth view every pixel is sky. Written by a compute shader.
  bool render(VkCommandBuffer commandBuffer, VkImageView color, VkImageView depth,
              VkImageLayout depthLayout, VkExtent2D extent, Error* error);

  // The sky and the sun's disc drawn inside the host's dynamic-rendering pass (colour
  // CreateInfo::skyPassColorFormat, depth CreateInfo::depthFormat, the extent of this frame's
  // dispatch()), after dispatch() this frame: a triangle over the screen at the far plane, depth
  // test EQUAL, no depth write. Drawn after the opaque geometry, it shades only the pixels the
  // geometry left at the far plane; it does not haze the geometry (read outputs()'s aerial
  // perspective where you shade it). Sets its own pipeline, descriptor set, viewport and
  // scissor. Needs the device's dynamicRendering feature.
  bool drawSky(VkCommandBuffer commandBuffer, Error* error);

  Outputs outputs() const;
  // The sky measured in frame `frameIndex`, which must have completed (and be one of the last
  // maxFramesInFlight frames).
  SkyLighting skyLighting(std::uint64_t frameIndex) const;
  MemoryUsage memoryUsage() const;
  std::vector<PassTiming> passTimings(std::uint64_t frameIndex) const;

 private:
  friend struct detail::ContextAccess;
  explicit Context(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// On the CPU, in double precision, by the same integral the transmittance LUT holds: the
// transmittance of sunlight from the top of the atmosphere down to `altitudeMetres` (planet
// centre straight below, as for the camera), 0 where the planet shadows it. For hosts lighting
// things by the sun (clouds at their altitude, terrain). `samples` along the path.
glm::vec3 sunTransmittance(const Parameters& parameters, double altitudeMetres,
                           const glm::dvec3& sunDirection, std::uint32_t samples = 64);

}  // namespace atmosphere
