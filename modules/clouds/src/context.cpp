// clouds::Context: the public API. It checks every argument, turns internal failures into
// Error codes (the API never throws) and forwards to Context::Impl.
#include <cmath>
#include <new>
#include <sstream>

#include "clouds/nvdf.h"
#include "context_impl.h"
#include "vkfx/api_boundary.h"

namespace clouds {

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::None:
      return "None";
    case ErrorCode::InvalidCreateInfo:
      return "InvalidCreateInfo";
    case ErrorCode::MissingFunction:
      return "MissingFunction";
    case ErrorCode::UnsupportedDevice:
      return "UnsupportedDevice";
    case ErrorCode::OutOfMemory:
      return "OutOfMemory";
    case ErrorCode::VulkanFailure:
      return "VulkanFailure";
    case ErrorCode::InvalidSettings:
      return "InvalidSettings";
    case ErrorCode::InvalidInputs:
      return "InvalidInputs";
    case ErrorCode::NotPrepared:
      return "NotPrepared";
    case ErrorCode::InvalidAsset:
      return "InvalidAsset";
  }
  return "?";
}

namespace {

using vkfx::checkExtent;
using vkfx::extentText;
using vkfx::fail;
using vkfx::finite;
using vkfx::finitePosition;
using vkfx::nonNegative;
using vkfx::succeed;

std::string checkCreateInfo(const CreateInfo& info) {
  if (std::string problem = vkfx::checkDeviceAndLimits(info); !problem.empty()) return problem;
  if (info.compositeColorFormat != VK_FORMAT_UNDEFINED &&
      info.compositeColorFormat != VK_FORMAT_R16G16B16A16_SFLOAT) {
    return "CreateInfo.compositeColorFormat = " +
           std::to_string(static_cast<int>(info.compositeColorFormat)) +
           ": only R16G16B16A16_SFLOAT (or UNDEFINED: no composite helper) is supported";
  }
  return {};
}

std::string checkTerrain(const FrameInputs::Terrain& t) {
  if (t.heightView == VK_NULL_HANDLE) return {};
  for (double c : {t.originMetres.x, t.originMetres.y}) {
    if (!std::isfinite(c)) return "FrameInputs.terrain.originMetres: must be finite";
  }
  for (double c : {t.sizeMetres.x, t.sizeMetres.y}) {
    if (!std::isfinite(c) || c <= 0.0) return "FrameInputs.terrain.sizeMetres: must be > 0";
  }
  if (!std::isfinite(t.minAltitudeMetres) || !std::isfinite(t.maxAltitudeMetres) ||
      t.maxAltitudeMetres < t.minAltitudeMetres || t.minAltitudeMetres < -20000.0f ||
      t.maxAltitudeMetres > 20000.0f) {
    return "FrameInputs.terrain.minAltitudeMetres = " + std::to_string(t.minAltitudeMetres) +
           ", maxAltitudeMetres = " + std::to_string(t.maxAltitudeMetres) +
           ": must be finite, min <= max, within [-20000, 20000]";
  }
  return {};
}

// This frame's weather regions: no more than the settings make room for, each placed finitely,
// with its sizes and look in range (both dispatch() and dispatchShadowMap() read them).
std::string checkWeatherRegions(std::span<const WeatherRegion> regions, const Settings& settings) {
  if (regions.size() > settings.weatherRegions) {
    return "FrameInputs.weatherRegions: " + std::to_string(regions.size()) +
           " regions, more than Settings.weatherRegions = " +
           std::to_string(settings.weatherRegions);
  }
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const WeatherRegion& r = regions[i];
    const std::string field = "FrameInputs.weatherRegions[" + std::to_string(i) + "]";
    if (!std::isfinite(r.centreMetres.x) || !std::isfinite(r.centreMetres.y)) {
      return field + ".centreMetres: must be finite";
    }
    if (!std::isfinite(r.headingDegrees)) return field + ".headingDegrees: must be finite";
    const struct {
      const char* name;
      float value;
      float lo;
      float hi;
    } ranged[] = {
        {"halfSidesMetres.x", r.halfSidesMetres.x, 0.0f, 1e7f},
        {"halfSidesMetres.y", r.halfSidesMetres.y, 0.0f, 1e7f},
        {"radiusMetres", r.radiusMetres, 0.0f, 1e7f},
        {"blendMetres", r.blendMetres, 100.0f, 1e7f},
        {"coverage", r.coverage, 0.0f, 1.0f},
        {"cloudType", r.cloudType, 0.0f, 1.0f},
        {"densityMultiplier", r.densityMultiplier, 0.0f, 1e6f},
        {"anvilBias", r.anvilBias, 0.0f, 1.0f},
        {"vortex.eyeRadiusMetres", r.vortex.eyeRadiusMetres, 0.0f, 1e6f},
        {"vortex.eyeWallMetres", r.vortex.eyeWallMetres, 100.0f, 1e6f},
        {"vortex.wallSpeedMetresPerSecond", r.vortex.wallSpeedMetresPerSecond, -200.0f, 200.0f},
        {"vortex.spiralArms", r.vortex.spiralArms, 0.0f, 8.0f}};
    for (const auto& [name, value, lo, hi] : ranged) {
      if (!(value >= lo && value <= hi)) {  // NaN fails too
        std::ostringstream out;
        out << field << "." << name << " = " << value << ": must be in [" << lo << ", " << hi
            << "]";
        return out.str();
      }
    }
    if (r.vortex.eyeRadiusMetres > 0.0f) {
      if (settings.superstorms == 0) {
        return field + ".vortex: a superstorm needs Settings.superstorms = 1";
      }
      if (r.halfSidesMetres != glm::vec2(0.0f)) {
        return field + ".halfSidesMetres: a superstorm's region is a disc (half sides 0)";
      }
      for (std::size_t j = 0; j < i; ++j) {
        if (regions[j].vortex.eyeRadiusMetres > 0.0f) {
          return field + ".vortex: one superstorm per frame (weatherRegions[" + std::to_string(j) +
                 "] is one)";
        }
      }
    }
  }
  return {};
}

// What both dispatch() and dispatchShadowMap() read: the command buffer, camera position, sun,
// time, terrain.
std::string checkSharedInputs(const FrameInputs& in) {
  if (std::string problem = checkTerrain(in.terrain); !problem.empty()) return problem;

  if (in.commandBuffer == VK_NULL_HANDLE) return "FrameInputs.commandBuffer: must not be null";
  for (double c : {in.cameraPosition.x, in.cameraPosition.y, in.cameraPosition.z}) {
    if (!std::isfinite(c)) return "FrameInputs.cameraPosition: must be finite";
  }
  if (!finite(in.sunDirection)) return "FrameInputs.sunDirection: must be finite";
  if (!std::isfinite(in.timeSeconds) || in.timeSeconds < 0.0) {
    return "FrameInputs.timeSeconds = " + std::to_string(in.timeSeconds) + ": must be >= 0";
  }
  if (in.windDisplacementMetres && !(std::isfinite(in.windDisplacementMetres->x) &&
                                     std::isfinite(in.windDisplacementMetres->y))) {
    return "FrameInputs.windDisplacementMetres: must be finite";
  }
  if (!(in.weatherBlend >= 0.0f && in.weatherBlend <= 1.0f)) {
    return "FrameInputs.weatherBlend = " + std::to_string(in.weatherBlend) + ": must be in [0, 1]";
  }
  if (in.weatherBlendView != VK_NULL_HANDLE && in.weatherView == VK_NULL_HANDLE) {
    return "FrameInputs.weatherBlendView: needs a weatherView to blend from";
  }
  return {};
}

// This frame's lightning: no more flashes than the settings make room for, each finite.
std::string checkFlashes(std::span<const LightningFlash> flashes, const Settings& settings) {
  if (flashes.size() > settings.lightningFlashes) {
    return "FrameInputs.lightningFlashes: " + std::to_string(flashes.size()) +
           " flashes, more than Settings.lightningFlashes = " +
           std::to_string(settings.lightningFlashes);
  }
  for (std::size_t i = 0; i < flashes.size(); ++i) {
    const LightningFlash& f = flashes[i];
    const std::string field = "FrameInputs.lightningFlashes[" + std::to_string(i) + "]";
    if (!finitePosition(f.positionMetres)) {
      return field + ".positionMetres: must be finite";
    }
    if (!std::isfinite(f.radiusMetres) || f.radiusMetres <= 0.0f) {
      return field + ".radiusMetres = " + std::to_string(f.radiusMetres) + ": must be > 0";
    }
    if (!finite(f.radiance) || !nonNegative(f.radiance)) {
      return field + ".radiance: must be finite and not negative";
    }
  }
  return {};
}

// This frame's bolts: no more pieces than the settings make room for, each finite.
std::string checkBolts(std::span<const LightningBoltSegment> bolts, const Settings& settings) {
  if (bolts.size() > settings.lightningBoltSegments) {
    return "FrameInputs.lightningBolts: " + std::to_string(bolts.size()) +
           " segments, more than Settings.lightningBoltSegments = " +
           std::to_string(settings.lightningBoltSegments);
  }
  for (std::size_t i = 0; i < bolts.size(); ++i) {
    const LightningBoltSegment& b = bolts[i];
    const std::string field = "FrameInputs.lightningBolts[" + std::to_string(i) + "]";
    if (!finitePosition(b.fromMetres) || !finitePosition(b.toMetres)) {
      return field + ": fromMetres and toMetres must be finite";
    }
    if (!std::isfinite(b.widthMetres) || b.widthMetres <= 0.0f) {
      return field + ".widthMetres = " + std::to_string(b.widthMetres) + ": must be > 0";
    }
    if (!finite(b.radiance) || !nonNegative(b.radiance)) {
      return field + ".radiance: must be finite and not negative";
    }
  }
  return {};
}

// This frame's hero clouds: no more than kMaxHeroClouds, of loaded assets, placed finitely.
std::string checkHeroClouds(std::span<const HeroCloud> clouds, std::size_t assets) {
  if (clouds.size() > kMaxHeroClouds) {
    return "FrameInputs.heroClouds: " + std::to_string(clouds.size()) + " clouds, more than the " +
           std::to_string(kMaxHeroClouds) + " a frame draws";
  }
  for (std::size_t i = 0; i < clouds.size(); ++i) {
    const HeroCloud& c = clouds[i];
    const std::string field = "FrameInputs.heroClouds[" + std::to_string(i) + "]";
    if (c.asset >= assets) {
      return field + ".asset = " + std::to_string(c.asset) + ": only " + std::to_string(assets) +
             " assets are loaded (Context::setHeroCloudAssets)";
    }
    if (!finitePosition(c.positionMetres)) return field + ".positionMetres: must be finite";
    if (!(c.scale >= 0.01f && c.scale <= 100.0f)) {
      return field + ".scale = " + std::to_string(c.scale) + ": must be in [0.01, 100]";
    }
    if (!std::isfinite(c.yawRadians)) return field + ".yawRadians: must be finite";
    if (!(c.growth >= 0.0f && c.growth <= 1.0f)) {
      return field + ".growth = " + std::to_string(c.growth) + ": must be in [0, 1]";
    }
    if (!(c.dissipation >= 0.0f && c.dissipation <= 1.0f)) {
      return field + ".dissipation = " + std::to_string(c.dissipation) + ": must be in [0, 1]";
    }
  }
  return {};
}

std::string checkInputs(const FrameInputs& in, const CreateInfo& info) {
  if (std::string problem = checkSharedInputs(in); !problem.empty()) return problem;
  if (std::string problem = checkExtent("FrameInputs.renderExtent", in.renderExtent, info);
      !problem.empty()) {
    return problem;
  }
  if (!finite(in.view)) return "FrameInputs.view: must be finite";
  if (!finite(in.projection)) return "FrameInputs.projection: must be finite";
  if (std::abs(glm::determinant(in.projection)) < 1e-30f) {
    return "FrameInputs.projection: must be invertible";
  }
  const struct {
    const char* field;
    const glm::vec3& value;
  } light[] = {{"FrameInputs.sunIlluminance", in.sunIlluminance},
               {"FrameInputs.ambientTop", in.ambientTop},
               {"FrameInputs.ambientBottom", in.ambientBottom}};
  for (const auto& [field, value] : light) {
    if (!finite(value) || !nonNegative(value)) {
      return std::string(field) + ": must be finite and not negative";
    }
  }
  if (in.groundAlbedo && (!finite(*in.groundAlbedo) || !nonNegative(*in.groundAlbedo) ||
                          glm::any(glm::greaterThan(*in.groundAlbedo, glm::vec3(1.0f))))) {
    return "FrameInputs.groundAlbedo: must be in [0, 1] per channel";
  }
  const FrameInputs::AerialPerspective& haze = in.aerialPerspective;
  if (haze.view != VK_NULL_HANDLE) {
    if (haze.slices == 0) return "FrameInputs.aerialPerspective.slices: must be >= 1";
    if (!std::isfinite(haze.rangeMetres) || haze.rangeMetres <= 0.0f) {
      return "FrameInputs.aerialPerspective.rangeMetres = " + std::to_string(haze.rangeMetres) +
             ": must be > 0";
    }
    if (!finite(haze.radianceScale) || !nonNegative(haze.radianceScale)) {
      return "FrameInputs.aerialPerspective.radianceScale: must be finite and not negative";
    }
    const struct {
      const char* field;
      const glm::vec3& value;
    } scattering[] = {
        {"FrameInputs.aerialPerspective.rayleighScatteringPerMetre",
         haze.rayleighScatteringPerMetre},
        {"FrameInputs.aerialPerspective.mieScatteringPerMetre", haze.mieScatteringPerMetre}};
    for (const auto& [field, value] : scattering) {
      if (!finite(value) || !nonNegative(value)) {
        return std::string(field) + ": must be finite and not negative";
      }
    }
    if (!(std::abs(haze.miePhaseG) < 1.0f)) {
      return "FrameInputs.aerialPerspective.miePhaseG = " + std::to_string(haze.miePhaseG) +
             ": must be in (-1, 1)";
    }
  }
  return {};
}

// Runs `work`, turning what it throws into the error out-parameter.
template <typename Work>
bool guarded(Error* error, Work&& work) {
  return vkfx::guarded(error, "clouds", std::forward<Work>(work));
}

}  // namespace

std::unique_ptr<Context> Context::create(const CreateInfo& info, Error* error) {
  if (std::string problem = checkCreateInfo(info); !problem.empty()) {
    fail(error, ErrorCode::InvalidCreateInfo, problem);
    return nullptr;
  }
  detail::VulkanFunctions functions;
  std::string missing;
  if (!functions.load(info.instance, info.device, info.getInstanceProcAddr, info.getDeviceProcAddr,
                      info.debugUtils, &missing)) {
    fail(error, ErrorCode::MissingFunction, "clouds: cannot load Vulkan function " + missing);
    return nullptr;
  }
  std::unique_ptr<Impl> impl;
  if (!guarded(error, [&] { impl = std::make_unique<Impl>(info, functions); })) return nullptr;
  return std::unique_ptr<Context>(new Context(std::move(impl)));
}

Context::Context(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Context::~Context() = default;

bool Context::prepare(const Settings& settings, VkExtent2D renderExtent, Error* error) {
  if (std::string problem = validateSettings(settings); !problem.empty()) {
    return fail(error, ErrorCode::InvalidSettings, problem);
  }
  const std::string problem = checkExtent("renderExtent", renderExtent, impl_->createInfo());
  if (!problem.empty()) return fail(error, ErrorCode::InvalidInputs, "prepare: " + problem);
  return guarded(error, [&] { impl_->prepare(settings, renderExtent); });
}

bool Context::setHeroCloudAssets(std::span<const NvdfVolume* const> assets, Error* error) {
  for (std::size_t i = 0; i < assets.size(); ++i) {
    const std::string field = "setHeroCloudAssets: assets[" + std::to_string(i) + "]";
    if (assets[i] == nullptr) return fail(error, ErrorCode::InvalidInputs, field + ": null");
    if (std::string problem = validateNvdf(*assets[i]); !problem.empty()) {
      return fail(error, ErrorCode::InvalidInputs, field + ": " + problem);
    }
  }
  return guarded(error, [&] { impl_->setHeroCloudAssets(assets); });
}

bool Context::prepared(const Settings& settings, VkExtent2D renderExtent) const {
  return validateSettings(settings).empty() &&
         checkExtent("", renderExtent, impl_->createInfo()).empty() &&
         impl_->unprepared(settings, renderExtent).empty();
}

bool Context::dispatch(const FrameInputs& inputs, const Settings& settings, Error* error) {
  if (std::string problem = checkInputs(inputs, impl_->createInfo()); !problem.empty()) {
    return fail(error, ErrorCode::InvalidInputs, problem);
  }
  if (std::string problem = validateSettings(settings); !problem.empty()) {
    return fail(error, ErrorCode::InvalidSettings, problem);
  }
  if (std::string problem = checkFlashes(inputs.lightningFlashes, settings); !problem.empty()) {
    return fail(error, ErrorCode::InvalidInputs, problem);
  }
  if (settings.skyLight && inputs.skyView == VK_NULL_HANDLE) {
    return fail(error, ErrorCode::InvalidInputs,
                "FrameInputs.skyView: Settings.skyLight lays the clouds over the host's sky, "
                "which it needs");
  }
  if (std::string problem = checkWeatherRegions(inputs.weatherRegions, settings);
      !problem.empty()) {
    return fail(error, ErrorCode::InvalidInputs, problem);
  }
  if (std::string problem = checkBolts(inputs.lightningBolts, settings); !problem.empty()) {
    return fail(error, ErrorCode::InvalidInputs, problem);
  }
  if (std::string problem = checkHeroClouds(inputs.heroClouds, impl_->heroCloudAssets());
      !problem.empty()) {
    return fail(error, ErrorCode::InvalidInputs, problem);
  }
  if (std::string missing = impl_->unprepared(settings, inputs.renderExtent); !missing.empty()) {
    return fail(error, ErrorCode::NotPrepared,
                "dispatch: " + missing +
                    " do not exist yet: call Context::prepare() with "
                    "these settings and render extent outside command recording");
  }
  impl_->dispatch(inputs, settings);
  return succeed(error);
}

bool Context::dispatchShadowMap(const FrameInputs& inputs, const Settings& settings, Error* error) {
  if (std::string problem = checkSharedInputs(inputs); !problem.empty()) {
    return fail(error, ErrorCode::InvalidInputs, "dispatchShadowMap: " + problem);
  }
  if (std::string problem = validateSettings(settings); !problem.empty()) {
    return fail(error, ErrorCode::InvalidSettings, problem);
  }
  if (std::string problem = checkWeatherRegions(inputs.weatherRegions, settings);
      !problem.empty()) {
    return fail(error, ErrorCode::InvalidInputs, "dispatchShadowMap: " + problem);
  }
  if (!impl_->shadowPrepared(settings)) {
    return fail(error, ErrorCode::NotPrepared,
                "dispatchShadowMap: the shadow map for these settings does not exist yet: call "
                "Context::prepare() with them outside command recording");
  }
  impl_->dispatchShadowMap(inputs, settings);
  return succeed(error);
}

bool Context::composite(VkCommandBuffer commandBuffer, VkImageView color, VkExtent2D extent,
                        Error* error) {
  if (impl_->createInfo().compositeColorFormat == VK_FORMAT_UNDEFINED) {
    return fail(error, ErrorCode::InvalidInputs,
                "composite: CreateInfo.compositeColorFormat was UNDEFINED (no composite helper)");
  }
  if (commandBuffer == VK_NULL_HANDLE || color == VK_NULL_HANDLE) {
    return fail(error, ErrorCode::InvalidInputs,
                "composite: command buffer and colour view are required");
  }
  const Outputs out = impl_->outputs();
  if (extent.width != out.extent.width || extent.height != out.extent.height) {
    return fail(error, ErrorCode::InvalidInputs,
                "composite: extent " + extentText(extent) +
                    " must equal the last dispatch's renderExtent (" + extentText(out.extent) +
                    ")");
  }
  impl_->composite(commandBuffer, color, extent);
  return succeed(error);
}

Outputs Context::outputs() const {
  return impl_->outputs();
}
FrameReport Context::lastFrameReport() const {
  return impl_->lastFrameReport();
}
MemoryUsage Context::memoryUsage() const {
  return impl_->memoryUsage();
}
WorkCounters Context::workCounters(std::uint64_t frameIndex) const {
  return impl_->workCounters(frameIndex);
}
std::vector<PassTiming> Context::passTimings(std::uint64_t frameIndex) const {
  return impl_->passTimings(frameIndex);
}
SkyLighting Context::skyLighting(std::uint64_t frameIndex) const {
  return impl_->skyLighting(frameIndex);
}

static_assert(kSkyLightExtent.width == shader::kSkyLightWidth &&
              kSkyLightExtent.height == shader::kSkyLightHeight);

}  // namespace clouds
