#pragma once
// Hero (voxel) clouds' part of the benchmark: seed 002's optimisation ladder (Nubis³,
// "Optimizations": base 10 ms, + voxel-based lighting 6.1, + adaptive & SDF ray-march 2.2) on
// views of the shipped towering cumulus alone (the layer empty), each rung against the voxel
// Reference (Settings::heroLight Marched, the straight integral towards the sun):
//   1. dense march, straight light march per sample: every step a voxel, and from each cloudy
//      sample the sun's optical depth marched at half a voxel to the box (HeroLight::Marched,
//      the Reference's light), no jumps, no coarse steps;
//   2. the same with High's light cone (HeroLight::Cone, 6 samples) instead: the base with the
//      layer's own cheap light march;
//   3. + voxel light volume (HeroLight::Volume);
//   4. + SDF and adaptive steps (empty-space skipping's signed-distance jumps, coarse steps).
// Every rung marches every pixel of a half-resolution trace each frame (no temporal reuse), so
// its time is the march's; frames are interleaved across rungs. The light volume's sweep,
// which runs only when its sun, cloud or life changes, is timed apart.
#include <ostream>
#include <string>
#include <vector>

#include "engine/gfx/device.h"

namespace bench {

struct VoxelMeasurement {
  std::string rung;
  std::string view;
  double frameMs = 0.0;  // the module's GPU time per frame, median of the timed frames
  double marchMs = 0.0;  // its march pass, median
  double psnr = 0.0;     // dB against the voxel Reference, tonemapped
  double meanAbs = 0.0;
  double viewSamplesPerRay = 0.0;
  double lightSamplesPerRay = 0.0;
};

struct VoxelResults {
  std::vector<std::string> rungs;
  std::vector<std::string> views;
  std::vector<VoxelMeasurement> measurements;
  double sweepMs = 0.0;  // one sweep of the cumulus's light volume, median

  const VoxelMeasurement* find(const std::string& rung, const std::string& view) const;
};

VoxelResults runVoxelLadder(engine::gfx::Device& device, VkExtent2D extent,
                            std::uint32_t timedFrames, std::uint32_t referenceFrames,
                            const std::vector<std::string>& onlyViews,
                            void (*progress)(const std::string& line));

// Rows of results.csv's columns: config the rung, view "voxel ladder: <view>", GPU time per
// frame (median), PSNR and mean error, samples per ray, the march's time.
void writeVoxelCsv(std::ostream& out, const VoxelResults& voxels);
void writeVoxelMarkdown(std::ostream& out, const VoxelResults& voxels);

}  // namespace bench
