// The harness's projection jitter (CloudView::projectionJitterPixels), through which the
// benchmark moves its Reference's rays inside their pixels: a jitter of one whole pixel shows
// each pixel what its neighbour showed without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cloud_harness.h"
#include "cloud_look.h"
#include "gpu_test.h"

namespace {

using clouds::tools::CloudFrame;
using clouds::tools::CloudView;

constexpr VkExtent2D kExtent{96, 54};

class HarnessJitterTest : public test::GpuTest {
 protected:
  static clouds::tools::CloudHarness& harness() {
    static clouds::tools::CloudHarness* h = new clouds::tools::CloudHarness(device(), kExtent);
    return *h;
  }
  // One frame with no ray jitter of the module's own: every pixel marched at its centre.
  static CloudFrame render(glm::vec2 jitterPixels) {
    const clouds::tools::LookScene scene = clouds::tools::noonCumulus();
    clouds::Settings settings = clouds::tools::singleFrame(clouds::tools::lookSettings(scene));
    settings.jitter = clouds::Jitter::None;
    CloudView view = scene.view;
    view.projectionJitterPixels = jitterPixels;
    harness().cut();
    return harness().render(view, settings, kExtent);
  }
  static const glm::vec4& at(const CloudFrame& f, std::uint32_t x, std::uint32_t y) {
    return f.radiance[std::size_t{y} * f.extent.width + x];
  }
  // The largest difference between `moved`'s pixels and `still`'s `dx`, `dy` pixels on, in
  // transmittance and in radiance relative to the image's brightest.
  static float largestDifference(const CloudFrame& moved, const CloudFrame& still, int dx, int dy) {
    float peak = 0.0f;
    for (const glm::vec4& p : still.radiance) peak = std::max(peak, p.g);
    float largest = 0.0f;
    for (std::uint32_t y = 0; y + std::uint32_t(dy) < kExtent.height; ++y) {
      for (std::uint32_t x = 0; x + std::uint32_t(dx) < kExtent.width; ++x) {
        const glm::vec4 a = at(moved, x, y);
        const glm::vec4 b = at(still, x + std::uint32_t(dx), y + std::uint32_t(dy));
        largest = std::max({largest, std::abs(a.a - b.a), std::abs(a.g - b.g) / peak});
      }
    }
    return largest;
  }
};

TEST_F(HarnessJitterTest, AWholePixelOfJitterShowsTheNeighboursRays) {
  const CloudFrame still = render(glm::vec2(0.0f));
  const CloudFrame right = render(glm::vec2(1.0f, 0.0f));
  const CloudFrame down = render(glm::vec2(0.0f, 1.0f));
  // The same rays, one pixel on (measured: 0.0004 and 0.0005, float rounding of the
  // directions); and the view has edges enough that the unmoved comparison differs plainly
  // (measured: 1, cloud against clear sky).
  EXPECT_LT(largestDifference(right, still, 1, 0), 0.01f);
  EXPECT_LT(largestDifference(down, still, 0, 1), 0.01f);
  EXPECT_GT(largestDifference(right, still, 0, 0), 0.1f);
  EXPECT_GT(largestDifference(down, still, 0, 0), 0.1f);
}

}  // namespace
