#pragma once
// Where the benchmark's Reference looks inside its pixels. The Reference mode's own subpixel
// sequence is the Halton (2, 3) one that temporal upsampling also walks inside each output
// pixel: averaged over those positions, the Reference would share a preset's own samples (High
// holds the first two Halton points of every output pixel after 128 frames) and flatter it by
// most of a decibel where aliasing dominates (far cloud rims seen from above the layer). So the
// bench marches the Reference at pixel centres and moves its rays through the projection to
// points of its own.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "cloud_harness.h"

namespace bench {

// The Reference of a view: `frames` frames of the Reference mode over `look` averaged, its rays
// moved through the pixels by referenceSubpixelOffset(), plus the first one alone (what a single
// Reference frame is worth) and each frame's GPU time.
struct Reference {
  std::vector<glm::vec3> pixels;       // averaged, tonemapped
  std::vector<glm::vec3> firstPixels;  // the first frame alone, tonemapped
  std::vector<double> milliseconds;
};
Reference renderReference(clouds::tools::CloudHarness& harness,
                          const clouds::tools::CloudView& view, const clouds::Settings& look,
                          VkExtent2D extent, std::uint32_t frames);

// Frame `i`'s offset from the pixel centre (pixels, in (-0.5, 0.5)): the centres of a 4 x 4
// grid over the pixel, in the order of a 4 x 4 Bayer matrix (every 4 frames in a row spread
// over the pixel), then again. 16 frames, or a multiple of it, average the grid exactly: a box
// filter with no shift of the image (its points' mean is the pixel centre). The grid's columns
// share Halton base-2 coordinates, but its rows (odd eighths) never meet the base-3 ones: the
// nearest of the module's first 16 Halton points is 0.06 pixel away.
inline glm::vec2 referenceSubpixelOffset(std::uint32_t i) {
  // The cell (x = cell % 4, y = cell / 4) frame i % 16 looks at: a 4 x 4 Bayer matrix's cells
  // in the order of their thresholds.
  constexpr std::uint32_t kCellOfFrame[16] = {0, 10, 2, 8, 5, 15, 7, 13, 1, 11, 3, 9, 4, 14, 6, 12};
  const std::uint32_t cell = kCellOfFrame[i % 16u];
  return (glm::vec2(float(cell % 4u), float(cell / 4u)) + 0.5f) / 4.0f - 0.5f;
}

}  // namespace bench
