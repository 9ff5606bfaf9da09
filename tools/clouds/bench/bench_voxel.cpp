#include "bench_voxel.h"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "bench_reference.h"
#include "bench_setup.h"
#include "cloud_harness.h"
#include "clouds/nvdf.h"
#include "engine/core/error.h"

namespace bench {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double passMs(const clouds::tools::CloudHarness& harness, const char* name) {
  double ms = 0.0;
  for (const clouds::PassTiming& pass : harness.lastPassTimings()) {
    if (std::string(pass.name) == name) ms += pass.milliseconds;
  }
  return ms;
}

struct Rung {
  const char* name;
  clouds::HeroLight light;
  bool jumps;  // SDF jumps and coarse steps
};
constexpr Rung kRungs[] = {
    {"dense march, straight light march per sample", clouds::HeroLight::Marched, false},
    {"dense march, light cone per sample", clouds::HeroLight::Cone, false},
    {"+ voxel light volume", clouds::HeroLight::Volume, false},
    {"+ SDF and adaptive steps", clouds::HeroLight::Volume, true},
};

struct VoxelView {
  std::string name;
  clouds::tools::CloudView view;
};

// The towering cumulus (2.1 km tall, 20 m voxels) with its base at 1.5 km, 2.6 km ahead.
std::vector<VoxelView> voxelViews() {
  clouds::HeroCloud cumulus;
  cumulus.positionMetres = {0.0, 1500.0, -2600.0};
  cumulus.yawRadians = 0.4f;
  clouds::tools::CloudView noon;
  noon.position = {0.0, 2300.0, 0.0};
  noon.pitchDegrees = 8.0;
  noon.sunElevationDegrees = 60.0;
  noon.sunAzimuthDegrees = 140.0;
  noon.heroClouds = {cumulus};
  clouds::tools::CloudView low = noon;
  low.sunElevationDegrees = 6.0;
  low.sunAzimuthDegrees = 15.0;
  low.sunIlluminance = {9.0f, 5.0f, 2.5f};
  clouds::tools::CloudView inside = noon;
  inside.position = {40.0, 2300.0, -2560.0};
  inside.yawDegrees = 30.0;
  inside.pitchDegrees = 0.0;
  return {{"voxel cumulus at noon", noon},
          {"voxel cumulus towards a low sun", low},
          {"inside the voxel cumulus", inside}};
}

// The look: the layer empty, so that the pictures are the hero cloud's.
clouds::Settings heroOnlyLook() {
  clouds::Settings look;
  look.coverage = 0.0f;
  return look;
}

clouds::Settings rungSettings(const Rung& rung) {
  clouds::Settings s = clouds::settingsFor(clouds::Quality::High, heroOnlyLook());
  s.updateInterval = 1;
  s.temporalReuse = false;
  s.temporalUpsampling = false;
  s.heroLight = rung.light;
  s.emptySpaceSkipping = rung.jumps;
  s.cheapSampling = rung.jumps;
  return s;
}

std::unique_ptr<clouds::tools::CloudHarness> harnessWithTheCumulus(
    engine::gfx::Device& device, VkExtent2D extent, const clouds::NvdfVolume& cumulus) {
  clouds::tools::HarnessOptions options;
  options.passTimings = true;
  options.workCounters = true;
  auto harness = std::make_unique<clouds::tools::CloudHarness>(device, extent, options);
  const clouds::NvdfVolume* assets[] = {&cumulus};
  clouds::Error error;
  if (!harness->context().setHeroCloudAssets(assets, &error)) {
    throw engine::Error("clouds_bench: " + error.message);
  }
  return harness;
}

}  // namespace

const VoxelMeasurement* VoxelResults::find(const std::string& rung, const std::string& view) const {
  for (const VoxelMeasurement& m : measurements) {
    if (m.rung == rung && m.view == view) return &m;
  }
  return nullptr;
}

VoxelResults runVoxelLadder(engine::gfx::Device& device, VkExtent2D extent,
                            std::uint32_t timedFrames, std::uint32_t referenceFrames,
                            const std::vector<std::string>& onlyViews,
                            void (*progress)(const std::string& line)) {
  VoxelResults results;
  clouds::Error error;
  const std::optional<clouds::NvdfVolume> cumulus =
      clouds::readNvdf(CLOUDS_HERO_CLOUD_DIR "/towering_cumulus.nvdf", &error);
  if (!cumulus) throw engine::Error("clouds_bench: " + error.message);
  for (const Rung& rung : kRungs) results.rungs.push_back(rung.name);
  auto reference = harnessWithTheCumulus(device, extent, *cumulus);
  std::vector<std::unique_ptr<clouds::tools::CloudHarness>> harnesses;
  for (std::size_t i = 0; i < std::size(kRungs); ++i) {
    harnesses.push_back(harnessWithTheCumulus(device, extent, *cumulus));
  }
  std::vector<double> sweeps;
  for (const VoxelView& view : voxelViews()) {
    if (!selected(onlyViews, view.name)) continue;
    results.views.push_back(view.name);
    progress(view.name + ": Reference");
    const Reference truth =
        renderReference(*reference, view.view, heroOnlyLook(), extent, referenceFrames);
    std::vector<std::vector<double>> frameMs(std::size(kRungs));
    std::vector<std::vector<double>> marchMs(std::size(kRungs));
    std::vector<clouds::WorkCounters> work(std::size(kRungs));
    for (std::uint32_t frame = 0; frame <= timedFrames; ++frame) {
      for (std::size_t i = 0; i < std::size(kRungs); ++i) {
        clouds::tools::CloudHarness& harness = *harnesses[i];
        const std::string problem = harness.tryRender(view.view, rungSettings(kRungs[i]), extent);
        if (!problem.empty()) throw engine::Error("clouds_bench: " + problem);
        // The first frame of a view sweeps the light volume (its sun is new): timed apart.
        if (frame == 0) {
          if (kRungs[i].light == clouds::HeroLight::Volume)
            sweeps.push_back(passMs(harness, "hero light"));
          continue;
        }
        frameMs[i].push_back(harness.lastGpuMilliseconds());
        marchMs[i].push_back(passMs(harness, "march"));
        const clouds::WorkCounters w = harness.lastWorkCounters();
        work[i].viewSamples += w.viewSamples;
        work[i].lightSamples += w.lightSamples;
        work[i].tracedPixels += w.tracedPixels;
      }
    }
    for (std::size_t i = 0; i < std::size(kRungs); ++i) {
      const clouds::tools::CloudFrame out =
          harnesses[i]->render(view.view, rungSettings(kRungs[i]), extent);
      const engine::assets::ImageError e =
          clouds::tools::imageError(clouds::tools::tonemappedPixels(out, view.view), truth.pixels);
      VoxelMeasurement m;
      m.rung = kRungs[i].name;
      m.view = view.name;
      m.frameMs = median(frameMs[i]);
      m.marchMs = median(marchMs[i]);
      m.psnr = e.psnr();
      m.meanAbs = e.meanAbs;
      const double rays = double(std::max<std::uint64_t>(work[i].tracedPixels, 1));
      m.viewSamplesPerRay = double(work[i].viewSamples) / rays;
      m.lightSamplesPerRay = double(work[i].lightSamples) / rays;
      results.measurements.push_back(m);
      progress(view.name + ", " + m.rung + ": " + std::to_string(m.frameMs) + " ms, " +
               std::to_string(m.psnr) + " dB");
    }
  }
  results.sweepMs = median(sweeps);
  return results;
}

void writeVoxelCsv(std::ostream& out, const VoxelResults& voxels) {
  for (const VoxelMeasurement& m : voxels.measurements) {
    out << '"' << m.rung << "\",voxel ladder,,0,\"voxel ladder: " << m.view << "\"," << m.frameMs
        << ",,," << m.psnr << ',' << m.psnr << ',' << m.meanAbs << ",," << m.viewSamplesPerRay
        << ',' << m.lightSamplesPerRay << ",,,," << m.marchMs << ",,,,\n";
  }
}

void writeVoxelMarkdown(std::ostream& out, const VoxelResults& voxels) {
  if (voxels.views.empty()) return;
  const auto format = [](const char* f, double v) {
    char text[64];
    std::snprintf(text, sizeof(text), f, v);
    return std::string(text);
  };
  out << "\n## Hero clouds: seed 002's optimisation ladder\n\n"
         "The shipped towering cumulus alone (the layer empty), every pixel of a half-resolution "
         "trace marched each frame (High's march without temporal reuse), against the voxel "
         "Reference (its light the straight integral towards the sun). GPU ms per frame (the "
         "march's in brackets) / dB. Seed 002 went 10 -> 6.1 -> 2.2 ms (4.5x).\n\n| rung |";
  for (const std::string& view : voxels.views) out << ' ' << view << " |";
  out << " mean ms | faster than the first |\n|---|";
  for (std::size_t i = 0; i < voxels.views.size() + 2; ++i) out << "---|";
  out << '\n';
  double first = 0.0;
  for (const std::string& rung : voxels.rungs) {
    out << "| " << rung << " |";
    double sum = 0.0;
    for (const std::string& view : voxels.views) {
      const VoxelMeasurement* m = voxels.find(rung, view);
      if (m == nullptr) continue;
      sum += m->frameMs;
      out << ' ' << format("%.1f", m->frameMs) << " (" << format("%.1f", m->marchMs) << ") / "
          << format("%.1f", m->psnr) << " |";
    }
    const double mean = sum / double(voxels.views.size());
    if (first == 0.0) first = mean;
    out << ' ' << format("%.1f", mean) << " | " << format("%.2fx", first / mean) << " |\n";
  }
  out << "\nOne sweep of the cumulus's light volume (when its sun, cloud or life changes): "
      << format("%.1f", voxels.sweepMs) << " ms.\n";
}

}  // namespace bench
