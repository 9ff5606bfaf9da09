// The packed texels of the temporal passes (shaders/cloud_temporal.h), compiled as C++: the
// output history's shared-exponent radiance, transmittance, front depth and own-sample count;
// and the filter that resamples the reprojected history.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cloud_temporal.h"

namespace {

using namespace clouds::shader;

TEST(CloudPacking, SharedExponentRadianceKeepsEachChannelToAFiveHundredthOfTheLargest) {
  for (const vec3 rgb :
       {vec3(1.0f, 1.0f, 1.0f), vec3(17.3f, 9.1f, 2.4f), vec3(0.003f, 0.0f, 2e-4f),
        vec3(1e-6f, 3e-6f, 2e-6f), vec3(40000.0f, 100.0f, 0.5f), vec3(0.999f, 0.5f, 1.001f)}) {
    const vec3 back = unpackSharedExponent(packSharedExponent(rgb));
    // Half a step of the largest channel's exponent; the smallest exponent's step is 2^-24.
    const float step = std::max(std::max({rgb.x, rgb.y, rgb.z}) / 512.0f, std::ldexp(1.0f, -24));
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(back[c], rgb[c], step) << rgb.x << " " << rgb.y << " " << rgb.z;
    }
    // What is read back packs to the same bits: a history kept in place does not drift.
    EXPECT_EQ(packSharedExponent(back), packSharedExponent(rgb));
  }
  EXPECT_EQ(unpackSharedExponent(packSharedExponent(vec3(0.0f))), vec3(0.0f));
  // Negative radiance is no radiance; beyond the format's range it saturates.
  EXPECT_EQ(unpackSharedExponent(packSharedExponent(vec3(-1.0f, 0.0f, 0.0f))), vec3(0.0f));
  EXPECT_EQ(unpackSharedExponent(packSharedExponent(vec3(1e9f, 0.0f, 0.0f))).x, 65408.0f);
}

TEST(CloudPacking, OutputHistoryKeepsTransmittanceFrontDepthAndCount) {
  for (const float transmittance : {0.0f, 1.0f, 0.37f, 0.9995f}) {
    for (const uint count : {0u, 1u, 4u, 15u}) {
      const uvec2 texel = packOutputHistory(vec4(2.0f, 1.5f, 1.0f, transmittance), 12345.0f, count);
      EXPECT_NEAR(unpackOutputHistory(texel).w, transmittance, 0.5f / 4095.0f);
      EXPECT_NEAR(unpackOutputHistory(texel).x, 2.0f, 2.0f / 512.0f);
      EXPECT_NEAR(outputHistoryFrontDepth(texel), 12345.0f, 12345.0f / 1024.0f);
      EXPECT_EQ(ownSampleCount(texel), count);
    }
  }
  EXPECT_EQ(ownSampleCount(packOutputHistory(vec4(1.0f), 0.0f, 40u)), 15u) << "saturates";
  EXPECT_EQ(outputHistoryFrontDepth(packOutputHistory(vec4(1.0f), 0.0f, 1u)), 0.0f) << "no cloud";
  EXPECT_TRUE(std::isfinite(outputHistoryFrontDepth(packOutputHistory(vec4(1.0f), 1e7f, 1u))))
      << "beyond 65 km the front is kept at 65 km";
  // A texel this pass never wrote (poisoned with half-float NaNs) says so by its front depth.
  EXPECT_TRUE(std::isnan(outputHistoryFrontDepth(uvec2(0x7E007E00u, 0x7E007E00u))));
}

// The reprojected history's resampling weights: they interpolate (a texel read at its centre
// is itself), sum to one, and reproduce a quadratic exactly, which bilinear weights do not
// (their error, f (1 - f) / 2 of the curvature, is the blur each frame adds).
TEST(HistoryResampling, CatmullRomWeightsInterpolateAndKeepCurvature) {
  EXPECT_EQ(catmullRomWeights(0.0f), vec4(0.0f, 1.0f, 0.0f, 0.0f));
  for (float f = 0.0f; f < 1.0f; f += 0.125f) {
    const vec4 w = catmullRomWeights(f);
    EXPECT_NEAR(w.x + w.y + w.z + w.w, 1.0f, 1e-6f) << f;
    // Texels at -1, 0, 1, 2 holding x^2: the point at f reads f^2.
    EXPECT_NEAR(w.x * 1.0f + w.z * 1.0f + w.w * 4.0f, f * f, 1e-6f) << f;
    EXPECT_NEAR(-w.x + w.z + 2.0f * w.w, f, 1e-6f) << f;
  }
}

}  // namespace
