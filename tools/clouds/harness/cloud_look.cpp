#include "cloud_look.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/render/scene_components.h"

namespace clouds::tools {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

double luminance(const glm::vec4& radiance) {
  return engine::render::luminance(glm::dvec3(glm::vec3(radiance)));
}

}  // namespace

CloudLook measureLook(const CloudFrame& frame, const CloudView& view,
                      const clouds::Settings& settings) {
  const double planetRadius = settings.planetRadiusMetres;
  const double bottom = settings.layerBottomMetres;
  const double thickness = double(settings.layerTopMetres) - bottom;
  // Heights above a spherical planet whose surface is at y = 0 below the origin.
  const glm::dvec3 planetCentre{0.0, -planetRadius, 0.0};
  std::vector<double> flank, base;
  CloudLook look;
  const PixelRays rays(view, frame.extent);
  for (std::uint32_t y = 0; y < frame.extent.height; ++y) {
    for (std::uint32_t x = 0; x < frame.extent.width; ++x) {
      const std::size_t i = std::size_t(y) * frame.extent.width + x;
      const glm::vec4 radiance = frame.radiance[i];
      if (!(radiance.a < kOpaqueTransmittance)) continue;
      ++look.cloudPixels;
      const double distance = frame.depth[i].y;  // transmittance-weighted: the seen surface
      const glm::dvec3 point = view.position + glm::dvec3(rays.direction(x, y)) * distance;
      const double altitude = glm::length(point - planetCentre) - planetRadius;
      const double heightFraction = (altitude - bottom) / thickness;
      const double l = luminance(radiance);
      if (heightFraction < kBaseHeightFraction) base.push_back(l);
      if (heightFraction > kFlankHeightFraction) flank.push_back(l);
    }
  }
  look.flankPixels = flank.size();
  look.basePixels = base.size();
  look.flankLuminance = median(std::move(flank));
  look.baseLuminance = median(std::move(base));
  if (look.flankPixels > 0 && look.basePixels > 0 && look.baseLuminance > 0.0) {
    look.flankToBase = look.flankLuminance / look.baseLuminance;
  }
  return look;
}

double meanRelativeChangeOverClouds(const CloudFrame& a, const CloudFrame& b) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.radiance.size() && i < b.radiance.size(); ++i) {
    if (!(a.radiance[i].a < kOpaqueTransmittance || b.radiance[i].a < kOpaqueTransmittance)) {
      continue;
    }
    const double la = luminance(a.radiance[i]);
    const double lb = luminance(b.radiance[i]);
    sum += std::abs(la - lb) / std::max(lb, 1e-6);
    ++count;
  }
  return count > 0 ? sum / double(count) : 0.0;
}

LookScene noonCumulus() {
  LookScene scene;
  CloudView& view = scene.view;
  view.position = {0.0, 300.0, 0.0};
  view.yawDegrees = 10.0;
  view.pitchDegrees = 20.0;
  view.verticalFovDegrees = 60.0f;
  // The sun of cumulus_noon.json at 12:00: 70 degrees up, behind the camera.
  view.sunElevationDegrees = 70.0;
  view.sunAzimuthDegrees = 180.0;
  // Light in physical units (kilolux, kcd/m^2) as the sample's Earth atmosphere over its
  // terrain gives it for that sun (engine::render::SkyLight, measured 2026-11-25): the sun's
  // illuminance at the middle of the layer, the zenith sky's radiance above, the band up to 10
  // degrees above the horizon beside, and below the ground (FrameInputs::groundAlbedo) of the
  // sample terrain's mean albedo (the sample logs it), lit by the sun where the clouds' shadow
  // map says and by the sky.
  view.sunIlluminance = {121.3f, 113.5f, 103.7f};
  view.ambientTop = {0.71f, 1.56f, 3.66f};
  view.ambientBottom = {3.53f, 6.58f, 10.24f};
  view.groundAlbedo = glm::vec3(0.095f, 0.115f, 0.076f);
  view.timeSeconds = 5.0;
  clouds::Settings& s = scene.settings;  // cumulus_noon.json's layer
  s.layerBottomMetres = 1600.0f;
  s.layerTopMetres = 3800.0f;
  s.coverage = 0.52f;
  s.cloudType = 1.0f;
  s.typeVariation = 0.2f;
  return scene;
}

clouds::Settings lookSettings(const LookScene& scene) {
  return singleFrame(clouds::settingsFor(clouds::Quality::High, scene.settings));
}

LookScene cumulusTowardsTheSun() {
  LookScene scene = noonCumulus();
  // Beside the large cumulus up and to the right of the noon view's centre.
  scene.view.sunElevationDegrees = 33.0;
  scene.view.sunAzimuthDegrees = scene.view.yawDegrees - 25.0;
  return scene;
}

double cloudLuminanceNearTheSun(const CloudFrame& frame, const CloudView& view, double degrees,
                                std::size_t* pixels) {
  const glm::dvec3 sun = glm::dvec3(sunDirection(view));
  const double cosLimit = std::cos(glm::radians(degrees));
  const PixelRays rays(view, frame.extent);
  double sum = 0.0;
  std::size_t count = 0;
  for (std::uint32_t y = 0; y < frame.extent.height; ++y) {
    for (std::uint32_t x = 0; x < frame.extent.width; ++x) {
      const glm::vec4 radiance = frame.radiance[std::size_t(y) * frame.extent.width + x];
      if (radiance.a > 0.95f) continue;
      if (glm::dot(glm::dvec3(rays.direction(x, y)), sun) < cosLimit) continue;
      sum += luminance(radiance);
      ++count;
    }
  }
  if (pixels != nullptr) *pixels = count;
  return count > 0 ? sum / double(count) : 0.0;
}

NearTheSun renderNearTheSun(CloudHarness& harness, VkExtent2D extent,
                            const std::function<void(clouds::Settings&)>& change) {
  const LookScene scene = cumulusTowardsTheSun();
  clouds::Settings settings = lookSettings(scene);
  if (change) change(settings);
  NearTheSun near;
  near.frame = harness.renderAveraged(scene.view, settings, extent, kLookFrames);
  near.luminance =
      cloudLuminanceNearTheSun(near.frame, scene.view, kNearTheSunDegrees, &near.pixels);
  return near;
}

}  // namespace clouds::tools
