#pragma once
// Measures of the clouds' look on a rendered frame, for the tests that hold each lighting term
// to a visible effect and for the review set's reported figures. The classic photographic
// description of a fair-weather cumulus at noon is "bright sunlit flanks over a flat grey
// base": flankToBase puts a number on it.
#include <cmath>
#include <cstddef>
#include <functional>

#include "cloud_harness.h"

namespace clouds::tools {

struct CloudLook {
  std::size_t cloudPixels = 0;  // opaque cloud (transmittance below kOpaqueTransmittance)
  std::size_t flankPixels = 0;  // opaque, seen surface above kFlankHeightFraction of the layer
  std::size_t basePixels = 0;   // opaque, seen surface below kBaseHeightFraction of the layer
  double flankLuminance = 0.0;  // median luminance (radiance units) of the flank pixels
  double baseLuminance = 0.0;   // median luminance of the base pixels
  double flankToBase = 0.0;     // flankLuminance / baseLuminance (0 when either set is empty)
};

// A pixel counts as cloud when its transmittance is below this (nearly opaque, so its radiance
// is the cloud's own and not the background's).
inline constexpr float kOpaqueTransmittance = 0.1f;
// The seen surface is where the transmittance-weighted depth puts it; its height as a fraction
// of the layer's thickness classifies it (cumulus bases are flat at the layer's bottom).
inline constexpr double kBaseHeightFraction = 0.1;
inline constexpr double kFlankHeightFraction = 0.3;

// `frame` rendered from `view` with `settings` (for the layer's bounds and planet radius).
CloudLook measureLook(const CloudFrame& frame, const CloudView& view,
                      const clouds::Settings& settings);

// Mean over the pixels that are cloud in either frame of |L_a - L_b| / L_b (L: luminance of
// the radiance): how much a change (a term switched off) alters the clouds, as a fraction.
double meanRelativeChangeOverClouds(const CloudFrame& a, const CloudFrame& b);

// The canonical look view: a fair-weather cumulus field at noon (sun 70 degrees up, the
// scene cumulus_noon.json's clouds), seen from 300 m looking up 20 degrees, lit in the
// proportions the project's atmosphere gives at noon (see cloud_look.cpp).
struct LookScene {
  CloudView view;
  clouds::Settings settings;
};
LookScene noonCumulus();

// The settings the look is measured with: High's lighting, every pixel marched every frame
// (the reconstruction is not what is measured), and the frames averaged per measurement (the
// rays move inside their pixels: a converged picture).
clouds::Settings lookSettings(const LookScene& scene);
inline constexpr std::uint32_t kLookFrames = 8;

// The same view and light with the sun in the frame (33 degrees up, beside a cumulus): the view
// of the forward-scattering lobe, the silver lining of thin cloud around the sun.
LookScene cumulusTowardsTheSun();

// Mean luminance (radiance units, premultiplied: thin edges count for their opacity) over the
// pixels within `degrees` of the sun whose cloud opacity is at least 5%; 0 when there are none.
// `pixels` (optional) receives their count.
double cloudLuminanceNearTheSun(const CloudFrame& frame, const CloudView& view, double degrees,
                                std::size_t* pixels = nullptr);

// The cloud around the sun: cumulusTowardsTheSun() rendered with lookSettings(), changed by
// `change` when one is given, and the cloud within kNearTheSunDegrees of the sun measured. Two
// of them, with and without a change, say what the change does there (e.g. the forward lobe's
// silver lining: the lobe made isotropic).
inline constexpr double kNearTheSunDegrees = 15.0;
struct NearTheSun {
  CloudFrame frame;    // (for a preview)
  double luminance;    // cloudLuminanceNearTheSun() of it
  std::size_t pixels;  // cloud pixels near the sun
};
NearTheSun renderNearTheSun(CloudHarness& harness, VkExtent2D extent,
                            const std::function<void(clouds::Settings&)>& change = {});

// |L_changed - L_base| / L_base of the two frames' luminance near the sun.
inline double relativeChange(const NearTheSun& changed, const NearTheSun& base) {
  return std::abs(changed.luminance - base.luminance) / base.luminance;
}

}  // namespace clouds::tools
