// clouds_preview: renders one view through the clouds module with key=value overrides and
// writes a preview PNG (development aid; not a test).
// Usage: clouds_preview OUT.png [width=320 height=180 frames=1 altitude=300 pitch=10 yaw=0
//        sunElevation=35 sunAzimuth=200 coverage=... extinction=... skew=... shear=... quality=0..4
//        reference=0 compare=0 ground=0 regions=0..8 storm=0|1 stormSeconds=0 groundAlbedo=a
//        cloudsOnClouds=0|1 ...]
// groundAlbedo=a: a grey ground of that albedo under the bases, and the shadow map made before
// each frame (which the march then reads: cloudsOnClouds=0 reads only the cone).
// regions=N: N weather regions, Stormy discs of 3 km (blended over 3 km more) 8 km apart in a
// row across the view 10 km ahead (the first straight ahead), the rest of the sky as set.
// storm=1: a Stormy superstorm centred 20 km ahead (eye 4 km, wall 4.5 km, 24 km eased out over
// 8 km, 45 m/s at the wall, 3 arms) as the first region, at stormSeconds on its clock.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "cloud_harness.h"
#include "clouds/weather.h"
#include "engine/core/error.h"
#include "engine/gfx/instance.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: clouds_preview OUT.png [key=value ...]\n");
    return 2;
  }
  std::map<std::string, double> kv;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto eq = arg.find('=');
    if (eq == std::string::npos) continue;
    kv[arg.substr(0, eq)] = std::atof(arg.substr(eq + 1).c_str());
  }
  auto get = [&](const char* key, double fallback) { return kv.count(key) ? kv[key] : fallback; };
  try {
    engine::gfx::InstanceDesc instanceDesc;
    instanceDesc.validation = get("validation", 0) != 0;
    engine::gfx::Instance instance(instanceDesc);
    engine::gfx::Device device(instance, engine::gfx::DeviceDesc{});
    const VkExtent2D extent{static_cast<std::uint32_t>(get("width", 320)),
                            static_cast<std::uint32_t>(get("height", 180))};
    clouds::tools::HarnessOptions harnessOptions;
    harnessOptions.passTimings = true;
    clouds::tools::CloudHarness harness(device, extent, harnessOptions);
    clouds::tools::CloudView view;
    view.position = {get("x", 0), get("altitude", 300), get("z", 0)};
    view.pitchDegrees = get("pitch", 10);
    view.yawDegrees = get("yaw", 0);
    view.sunElevationDegrees = get("sunElevation", 35);
    view.sunAzimuthDegrees = get("sunAzimuth", 200);
    view.groundDepth = get("ground", 0) != 0;
    if (kv.count("groundAlbedo")) view.groundAlbedo = glm::vec3(float(get("groundAlbedo", 0.1)));
    view.timeSeconds = get("time", 0);
    // The preset first (quality=0..3), then every key given overrides its field.
    clouds::Settings s;
    if (kv.count("quality"))
      s = clouds::settingsFor(static_cast<clouds::Quality>(get("quality", 2)), s);
    s.coverage = static_cast<float>(get("coverage", s.coverage));
    s.cloudType = static_cast<float>(get("type", s.cloudType));
    s.extinctionPerMetre = static_cast<float>(get("extinction", s.extinctionPerMetre));
    s.densityMultiplier = static_cast<float>(get("density", s.densityMultiplier));
    s.detailErosion = static_cast<float>(get("erosion", s.detailErosion));
    s.shapeTileMetres = static_cast<float>(get("shapeTile", s.shapeTileMetres));
    s.maxViewSteps = static_cast<std::uint32_t>(get("steps", s.maxViewSteps));
    s.lightSteps = static_cast<std::uint32_t>(get("lightSteps", s.lightSteps));
    s.inScatterStrength = static_cast<float>(get("inScatter", s.inScatterStrength));
    s.ambientStrength = static_cast<float>(get("ambient", s.ambientStrength));
    s.detailTileMetres = static_cast<float>(get("detailTile", s.detailTileMetres));
    s.msExtinctionScale = static_cast<float>(get("msA", s.msExtinctionScale));
    s.msContribution = static_cast<float>(get("msB", s.msContribution));
    s.msEccentricityScale = static_cast<float>(get("msC", s.msEccentricityScale));
    s.multipleScatteringOctaves =
        static_cast<std::uint32_t>(get("msN", s.multipleScatteringOctaves));
    s.phaseForwardG = static_cast<float>(get("g", s.phaseForwardG));
    s.layerBottomMetres = static_cast<float>(get("bottom", s.layerBottomMetres));
    s.layerTopMetres = static_cast<float>(get("top", s.layerTopMetres));
    s.viewStepMetres = static_cast<float>(get("step", s.viewStepMetres));
    s.anvilBias = static_cast<float>(get("anvil", s.anvilBias));
    s.skewMetres = static_cast<float>(get("skew", s.skewMetres));
    s.windShearDegrees = static_cast<float>(get("shear", s.windShearDegrees));
    if (kv.count("detailDistance")) s.detailDistanceMetres = float(get("detailDistance", 0));
    if (kv.count("cutoff")) s.transmittanceCutoff = float(get("cutoff", 0));
    if (kv.count("maxSteps")) s.maxViewSteps = std::uint32_t(get("maxSteps", 0));
    if (kv.count("cheap")) s.cheapSampling = get("cheap", 1) != 0;
    if (kv.count("detail")) s.detail = get("detail", 1) != 0;
    if (kv.count("emptySpace")) s.emptySpaceSkipping = get("emptySpace", 1) != 0;
    if (kv.count("noiseLod")) s.noiseLevelOfDetail = get("noiseLod", 1) != 0;
    if (kv.count("upsampling")) s.temporalUpsampling = get("upsampling", 1) != 0;
    if (kv.count("traceScale")) s.traceScale = float(get("traceScale", 0.5));
    if (kv.count("interval")) s.updateInterval = std::uint32_t(get("interval", 16));
    if (kv.count("growth")) s.viewStepGrowth = float(get("growth", 0.004));
    if (kv.count("cloudsOnClouds")) s.cloudShadowsOnClouds = get("cloudsOnClouds", 1) != 0;
    if (get("reference", 0) != 0) {
      s = clouds::referenceSettings(s);
      if (kv.count("referenceLightSteps"))
        s.lightSteps = std::uint32_t(get("referenceLightSteps", 24));
    }
    const glm::vec3 ahead = clouds::tools::forwardDirection(view);
    const glm::dvec2 forward = glm::normalize(glm::dvec2(ahead.x, ahead.z));
    if (get("storm", 0) != 0) {
      clouds::WeatherRegion storm;
      storm.centreMetres = glm::dvec2(view.position.x, view.position.z) + 20000.0 * forward;
      storm.radiusMetres = 24000.0f;
      storm.blendMetres = 8000.0f;
      storm = clouds::withWeather(storm, clouds::weatherPreset(clouds::WeatherPreset::Stormy));
      storm.vortex.eyeRadiusMetres = 4000.0f;
      storm.vortex.eyeWallMetres = 4500.0f;
      storm.vortex.wallSpeedMetresPerSecond = 45.0f;
      view.weatherRegions.push_back(storm);
      view.timeSeconds = get("stormSeconds", 0.0);
      s.superstorms = 1;
    }
    for (int i = 0; i < int(get("regions", 0)); ++i) {
      clouds::WeatherRegion region;
      const double across = 8000.0 * ((i + 1) / 2) * (i % 2 ? 1.0 : -1.0);
      region.centreMetres = glm::dvec2(view.position.x, view.position.z) + 10000.0 * forward +
                            across * glm::dvec2(-forward.y, forward.x);
      region.radiusMetres = 3000.0f;
      region.blendMetres = 3000.0f;
      view.weatherRegions.push_back(
          clouds::withWeather(region, clouds::weatherPreset(clouds::WeatherPreset::Stormy)));
    }
    s.weatherRegions = static_cast<std::uint32_t>(view.weatherRegions.size());
    const auto start = std::chrono::steady_clock::now();
    // average=N: the mean of N frames after a cut (the Reference's supersampling), else the
    // last of `frames` frames.
    const clouds::tools::CloudFrame frame =
        kv.count("average")
            ? harness.renderAveraged(view, s, extent, static_cast<std::uint32_t>(get("average", 8)))
            : harness.render(view, s, extent, static_cast<std::uint32_t>(get("frames", 1)));
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    engine::assets::writePng(
        argv[1], clouds::tools::previewImage(frame, view, static_cast<float>(get("exposure", 1))));
    if (const int repeats = static_cast<int>(get("timing", 0)); repeats > 0) {
      // Median GPU time of the module's frame after the first (JIT and noise) frames.
      std::vector<double> times;
      std::map<std::string, std::vector<double>> passes;
      for (int i = 0; i < repeats; ++i) {
        harness.render(view, s, extent);
        times.push_back(harness.lastGpuMilliseconds());
        for (const clouds::PassTiming& t : harness.lastPassTimings())
          passes[t.name].push_back(t.milliseconds);
      }
      auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
      };
      std::sort(times.begin(), times.end());
      std::printf("GPU time %ux%u: median %.1f ms, min %.1f, max %.1f over %d frames\n",
                  extent.width, extent.height, times[times.size() / 2], times.front(), times.back(),
                  repeats);
      std::printf("median per pass:");
      for (const auto& [name, values] : passes)
        std::printf(" %s %.2f ms;", name.c_str(), median(values));
      std::printf("\n");
    }
    if (get("dumpTextures", 0) != 0) {
      // Weather map (RGB) and slice 0 of the shape and detail noise (R, G, B, A side by side).
      const auto weather = harness.readWeatherMap();
      engine::assets::writePng(std::string(argv[1]) + ".weather.png",
                               engine::assets::ImageRgba8{512, 512, weather});
      auto slices = [&](const std::vector<std::uint8_t>& texels, std::uint32_t size) {
        engine::assets::ImageRgba8 image{size * 4, size, {}};
        image.pixels.resize(std::size_t{16} * size * size);
        for (std::uint32_t y = 0; y < size; ++y) {
          for (std::uint32_t c = 0; c < 4; ++c) {
            for (std::uint32_t x = 0; x < size; ++x) {
              const std::uint8_t v = texels[4 * (std::size_t{y} * size + x) + c];
              std::uint8_t* out = &image.pixels[4 * (std::size_t{y} * size * 4 + c * size + x)];
              out[0] = out[1] = out[2] = v;
              out[3] = 255;
            }
          }
        }
        return image;
      };
      engine::assets::writePng(std::string(argv[1]) + ".shape.png",
                               slices(harness.readShapeNoise(), 128));
      engine::assets::writePng(std::string(argv[1]) + ".detail.png",
                               slices(harness.readDetailNoise(), 32));
    }
    if (get("compare", 0) != 0) {
      // Error against the Reference mode of the same view (a fresh renderer).
      clouds::tools::CloudHarness reference(device, extent);
      const clouds::tools::CloudFrame truth =
          reference.render(view, clouds::referenceSettings(s), extent);
      engine::assets::writePng(std::string(argv[1]) + ".reference.png",
                               clouds::tools::previewImage(truth, view));
      const engine::assets::ImageError e =
          clouds::tools::imageError(clouds::tools::tonemappedPixels(frame, view),
                                    clouds::tools::tonemappedPixels(truth, view));
      std::printf("vs reference: PSNR %.2f dB, mean abs %.4f, max abs %.4f\n", e.psnr(), e.meanAbs,
                  e.maxAbs);
    }
    double coverage = 0.0;
    for (const auto& p : frame.radiance) coverage += 1.0 - p.a;
    float minT = 1.0f;
    float maxL = 0.0f;
    for (const auto& p : frame.radiance) {
      minT = std::min(minT, p.a);
      maxL = std::max(maxL, std::max(p.r, std::max(p.g, p.b)));
    }
    std::printf(
        "wrote %s (%.0f ms wall incl. noise generation; mean opacity %.3f, min T %.3f, "
        "max radiance %.2f)\n",
        argv[1], ms, coverage / double(frame.radiance.size()), minT, maxL);
  } catch (const engine::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
