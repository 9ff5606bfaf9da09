// clouds_look: the look of the clouds in figures. Renders the canonical noon cumulus view
// (cloud_look.h: physical noon light, seen from the ground) converged at full resolution, and
// prints the HDR luminance ratio of sunlit flank to base, then what switching each lighting
// term off does to it, to the clouds' luminance and to the cloud around the sun in the view
// towards it. Optionally writes the previews as PNG.
// Usage: clouds_look [OUT_DIR] [--width W --height H]
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cloud_harness.h"
#include "cloud_look.h"
#include "engine/core/error.h"
#include "engine/gfx/instance.h"

namespace {

// The previews' exposure: noon cloud of ~10 kcd/m^2 to a light grey.
constexpr float kPreviewExposure = 0.08f;
// Cloud around the sun is brighter: exposed lower so its gradations stay below white.
constexpr float kNearTheSunExposure = 0.03f;

using clouds::tools::CloudFrame;
using clouds::tools::CloudLook;

struct TermOff {
  const char* name;
  std::function<void(clouds::Settings&)> apply;
};

const std::vector<TermOff>& termsOff() {
  static const std::vector<TermOff> terms = {
      {"in-scatter probability", [](clouds::Settings& s) { s.inScatterStrength = 0.0f; }},
      {"multiple scattering", [](clouds::Settings& s) { s.multipleScatteringOctaves = 1; }},
      {"ambient occlusion", [](clouds::Settings& s) { s.ambientOcclusionStrength = 0.0f; }},
      {"ambient", [](clouds::Settings& s) { s.ambientStrength = 0.0f; }},
  };
  return terms;
}

// The phase functions held against each other: the seeds' max() of two lobes (Schneider 2017)
// and the mix with a silver lobe max()ed in, against the mix alone. Each is normalised.
struct PhaseVariant {
  const char* name;
  std::function<void(clouds::Settings&)> apply;
};

// A silver lobe of `intensity` x HG(0.99 - spread) max()ed into the mix, or (`seeds`) into the
// seeds' single HG(0.6) lobe.
std::function<void(clouds::Settings&)> silver(float intensity, float spread, bool seeds) {
  return [=](clouds::Settings& s) {
    if (seeds) {
      s.phaseForwardG = 0.6f;
      s.phaseBackwardWeight = 0.0f;
    }
    s.silverIntensity = intensity;
    s.silverSpread = spread;
  };
}

const std::vector<PhaseVariant>& phaseVariants() {
  static const std::vector<PhaseVariant> variants = {
      {"mix (0.8, -0.3, 0.3): default", [](clouds::Settings&) {}},
      {"seeds: max(HG 0.6, HG 0.89)", silver(1.0f, 0.1f, true)},
      {"seeds: max(HG 0.6, .5 HG 0.94)", silver(0.5f, 0.05f, true)},
      {"max(mix, HG 0.89)", silver(1.0f, 0.1f, false)},
      {"max(mix, .5 HG 0.94)", silver(0.5f, 0.05f, false)},
      {"max(mix, 2 HG 0.94)", silver(2.0f, 0.05f, false)},
  };
  return variants;
}

// The light that reaches cloud bases from the ground (FrameInputs::groundAlbedo), varied.
struct GroundVariant {
  const char* name;
  std::function<void(clouds::tools::CloudView&, clouds::Settings&)> apply;
};

const std::vector<GroundVariant>& groundVariants() {
  static const std::vector<GroundVariant> variants = {
      {"no ground: the horizon lights bases",
       [](clouds::tools::CloudView& v, clouds::Settings&) { v.groundAlbedo.reset(); }},
      {"ground out of the clouds' shadow",
       [](clouds::tools::CloudView&, clouds::Settings& s) { s.shadowCascades = 0; }},
      {"ground albedo 0.3 (Earth's mean)",
       [](clouds::tools::CloudView& v, clouds::Settings&) { v.groundAlbedo = glm::vec3(0.3f); }},
  };
  return variants;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"clouds_look: the look of the clouds in figures (and, given a folder, pictures)"};
  std::filesystem::path outDir;
  VkExtent2D extent{320, 180};
  cli.add_option("out_dir", outDir, "Folder for the previews (PNG); none: figures only");
  cli.add_option("--width", extent.width, "Render width")->check(CLI::Range(16u, 4096u));
  cli.add_option("--height", extent.height, "Render height")->check(CLI::Range(16u, 4096u));
  CLI11_PARSE(cli, argc, argv);
  try {
    engine::gfx::Instance instance(engine::gfx::InstanceDesc{});
    engine::gfx::Device device(instance, engine::gfx::DeviceDesc{});
    clouds::tools::CloudHarness harness(device, extent);
    const clouds::tools::LookScene scene = clouds::tools::noonCumulus();
    const auto render = [&](const clouds::Settings& s) {
      return harness.renderAveraged(scene.view, s, extent, clouds::tools::kLookFrames);
    };
    const clouds::Settings look = clouds::tools::lookSettings(scene);
    const CloudFrame full = render(look);
    const CloudLook base = clouds::tools::measureLook(full, scene.view, look);
    const clouds::tools::NearTheSun nearTheSun = clouds::tools::renderNearTheSun(harness, extent);
    std::printf("noon cumulus, %ux%u, High lighting at full resolution (%u frames averaged)\n",
                extent.width, extent.height, clouds::tools::kLookFrames);
    std::printf("  cloud pixels %zu (flank %zu, base %zu)\n", base.cloudPixels, base.flankPixels,
                base.basePixels);
    std::printf("  flank %.2f, base %.2f kcd/m^2: flank/base %.2f\n", base.flankLuminance,
                base.baseLuminance, base.flankToBase);
    if (!outDir.empty()) {
      std::filesystem::create_directories(outDir);
      engine::assets::writePng(outDir / "noon_cumulus.png",
                               clouds::tools::previewImage(full, scene.view, kPreviewExposure));
    }
    for (const TermOff& term : termsOff()) {
      clouds::Settings s = look;
      term.apply(s);
      const CloudFrame off = render(s);
      const CloudLook l = clouds::tools::measureLook(off, scene.view, s);
      const double towardsTheSun = clouds::tools::relativeChange(
          clouds::tools::renderNearTheSun(harness, extent, term.apply), nearTheSun);
      std::printf(
          "  %-24s off: flank %.2f, base %.2f: flank/base %.2f; clouds' luminance changed "
          "%.1f%%, towards the sun %.1f%%\n",
          term.name, l.flankLuminance, l.baseLuminance, l.flankToBase,
          100.0 * clouds::tools::meanRelativeChangeOverClouds(off, full), 100.0 * towardsTheSun);
    }
    std::printf("the ground beneath (the sample terrain's albedo, in the clouds' shadow):\n");
    for (const GroundVariant& variant : groundVariants()) {
      clouds::tools::CloudView view = scene.view;
      clouds::Settings s = look;
      variant.apply(view, s);
      const CloudFrame frame = harness.renderAveraged(view, s, extent, clouds::tools::kLookFrames);
      const CloudLook l = clouds::tools::measureLook(frame, view, s);
      std::printf("  %-36s flank %.2f, base %.2f: flank/base %.2f\n", variant.name,
                  l.flankLuminance, l.baseLuminance, l.flankToBase);
    }
    // Forward scattering towards the sun: the mix's forward lobe and the silver lining.
    const clouds::tools::NearTheSun isotropic = clouds::tools::renderNearTheSun(
        harness, extent, [](clouds::Settings& s) { s.phaseForwardG = 0.0f; });
    if (!outDir.empty()) {
      engine::assets::writePng(
          outDir / "cumulus_towards_the_sun.png",
          clouds::tools::previewImage(nearTheSun.frame, clouds::tools::cumulusTowardsTheSun().view,
                                      kPreviewExposure));
    }
    std::printf(
        "towards the sun: cloud within %.0f degrees of it (%zu pixels) %.2f kcd/m^2, %.2f with "
        "the forward lobe off (g = 0)\n",
        clouds::tools::kNearTheSunDegrees, nearTheSun.pixels, nearTheSun.luminance,
        isotropic.luminance);
    std::printf(
        "phase functions (each normalised): the noon view's flank and base (kcd/m^2); the "
        "cloud near the sun\n");
    for (const PhaseVariant& variant : phaseVariants()) {
      clouds::Settings s = look;
      variant.apply(s);
      const CloudFrame frame = render(s);
      const CloudLook l = clouds::tools::measureLook(frame, scene.view, s);
      const clouds::tools::NearTheSun sun =
          clouds::tools::renderNearTheSun(harness, extent, variant.apply);
      std::printf("  %-32s flank %.2f, base %.2f: flank/base %.2f; near the sun %.2f kcd/m^2\n",
                  variant.name, l.flankLuminance, l.baseLuminance, l.flankToBase, sun.luminance);
      if (!outDir.empty()) {
        std::string file = std::string("phase_") + variant.name;
        for (char& c : file) {
          if (std::strchr(" (),:.", c) != nullptr) c = '_';
        }
        engine::assets::writePng(
            outDir / (file + ".png"),
            clouds::tools::previewImage(sun.frame, clouds::tools::cumulusTowardsTheSun().view,
                                        kNearTheSunExposure));
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clouds_look: %s\n", e.what());
    return 1;
  }
  return 0;
}
