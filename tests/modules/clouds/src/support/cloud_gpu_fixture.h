#pragma once
// Shared by the module's GPU tests that render with the harness: a fixture whose renderer()
// counts its work and times its passes, a canonical view, and checks on frames.
#include <cmath>
#include <memory>

#include "cloud_harness.h"
#include "context_access.h"
#include "gpu_test.h"

namespace test {

using clouds::tools::CloudFrame;
using clouds::tools::CloudView;

inline constexpr VkExtent2D kExtent{160, 90};

class CloudGpuTest : public test::GpuTest {
 protected:
  // A renderer that counts its work; created per test, so each starts with no history.
  static std::unique_ptr<clouds::tools::CloudHarness> renderer() {
    clouds::tools::HarnessOptions options;
    options.workCounters = true;
    options.passTimings = true;
    return std::make_unique<clouds::tools::CloudHarness>(device(), kExtent, options);
  }
};

// A fixture whose tests share one harness (and one noise generation) per test binary, of
// Width x Height at most, and reach the module's internals: test-only uniform flags for a
// scope, the last uniforms.
template <std::uint32_t Width, std::uint32_t Height>
class SharedHarnessTest : public test::GpuTest {
 protected:
  // Sets test-only uniform flags for a scope (also when an assertion returns early).
  struct DebugFlags {
    explicit DebugFlags(std::uint32_t flags) { impl().setDebugFlags(flags); }
    ~DebugFlags() { impl().setDebugFlags(0); }
  };
  static clouds::Context::Impl& impl() {
    return clouds::detail::ContextAccess::impl(harness().context());
  }
  static clouds::tools::CloudHarness& harness() {
    static clouds::tools::CloudHarness* h =
        new clouds::tools::CloudHarness(device(), {Width, Height});
    return *h;
  }
};

// Scattered cumulus seen from the ground, looking a little up (the sample's usual view).
inline CloudView cumulusView() {
  CloudView view;
  view.position = {0.0, 300.0, 0.0};
  view.pitchDegrees = 20.0;
  view.yawDegrees = 270.0;
  view.timeSeconds = 5.0;
  return view;
}

inline double meanOpacity(const clouds::tools::CloudFrame& frame) {
  double sum = 0.0;
  for (const glm::vec4& p : frame.radiance) sum += 1.0 - p.a;
  return sum / double(frame.radiance.size());
}

inline bool allValid(const clouds::tools::CloudFrame& frame) {
  for (const glm::vec4& p : frame.radiance) {
    for (int c = 0; c < 4; ++c) {
      if (!std::isfinite(p[c]) || p[c] < 0.0f) return false;
    }
    if (p.a > 1.0f) return false;
  }
  for (const glm::vec2& d : frame.depth) {
    if (!std::isfinite(d.x) || !std::isfinite(d.y) || d.x < 0.0f || d.y < 0.0f) return false;
  }
  return true;
}

inline float maxAbsDifference(const clouds::tools::CloudFrame& a,
                              const clouds::tools::CloudFrame& b) {
  float worst = 0.0f;
  for (std::size_t i = 0; i < a.radiance.size(); ++i) {
    const glm::vec4 d = glm::abs(a.radiance[i] - b.radiance[i]);
    worst = std::max({worst, d.r, d.g, d.b, d.a});
  }
  return worst;
}

inline std::uint64_t samples(const clouds::WorkCounters& c) {
  return c.viewSamples + c.lightSamples;
}

}  // namespace test
