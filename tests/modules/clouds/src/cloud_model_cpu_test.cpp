// The ray-march of the shared model on the CPU, with analytic answers: a homogeneous slab's
// transmittance and single-scattered radiance (which converges as steps double), and the white
// furnace (unit ambient, albedo 1: every pixel composites to exactly 1 over a unit background).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "cloud_march.h"
#include "cloud_temporal.h"
#include "cpu_reference.h"
#include "synthetic_textures.h"
#include "uniforms.h"

namespace {

using namespace clouds::shader;

const clouds::tools::CpuTextures& textures() {
  static const clouds::tools::CpuTextures t = test::syntheticTextures();
  return t;
}

// Uniforms for a camera at `altitude` looking straight up (or along `pitch`), tiny image.
CloudUniforms uniformsFor(const clouds::Settings& s, double altitude, double pitchDegrees,
                          VkExtent2D extent, const glm::vec3& sun = {0, 1, 0}) {
  clouds::tools::CloudView view;
  view.position = {0.0, altitude, 0.0};
  view.pitchDegrees = pitchDegrees;
  view.verticalFovDegrees = 1.0f;  // nearly parallel rays: every pixel sees the same path
  clouds::FrameInputs in;
  in.view = clouds::tools::viewMatrix(view);
  in.projection = clouds::tools::projectionMatrix(view, extent);
  in.cameraPosition = view.position;
  in.sunDirection = sun;
  in.sunIlluminance = glm::vec3(1.0f);
  in.ambientTop = glm::vec3(0.0f);
  in.ambientBottom = glm::vec3(0.0f);
  clouds::detail::UniformContext context;
  context.traceExtent = extent;
  context.fullExtent = extent;
  return clouds::detail::buildUniforms(in, s, context);
}

clouds::Settings slabSettings(float sigma, float stepMetres) {
  clouds::Settings s;
  s.extinctionPerMetre = sigma;
  s.densityMultiplier = 1.0f;
  s.viewStepMetres = stepMetres;
  s.viewStepGrowth = 0.0f;
  s.maxViewSteps = 16384;
  s.transmittanceCutoff = 0.0f;
  s.cheapSampling = false;
  s.multipleScattering = false;
  s.inScatterStrength = 0.0f;
  s.ambientOcclusionStrength = 0.0f;
  s.jitter = clouds::Jitter::None;
  s.emptySpaceSkipping = false;   // the homogeneous test slab ignores the weather map
  s.lightEveryOtherStep = false;  // every sample's own light (LightReuse... tests the reuse)
  return s;
}

TEST(CloudModelCpu, HomogeneousSlabTransmittanceMatchesBeerLambert) {
  const VkExtent2D extent{1, 1};
  for (double tau : {0.0, 1e-3, 0.1, 1.0, 5.0, 20.0, 100.0, 1e4}) {
    for (double pitch : {90.0, 30.0, 5.0}) {
      for (float step : {400.0f, 200.0f, 100.0f, 50.0f}) {
        const double thickness = 2500.0;
        // Path through the shell for this pitch (from the camera at 300 m), in double.
        CloudUniforms u = uniformsFor(slabSettings(1.0f, step), 300.0, pitch, extent);
        const vec3 dir = pixelRayDirection(vec2(0.5f, 0.5f), vec2(1.0f, 1.0f), u);
        const vec2 segment = layerSegment(300.0f, dir.y, u);
        const double path = double(segment.y) - double(segment.x);
        ASSERT_GE(path, thickness * 0.999);
        const float sigma = static_cast<float>(tau / thickness);
        u = uniformsFor(slabSettings(sigma, step), 300.0, pitch, extent);
        u.flags |= kFlagHomogeneous;
        const auto frame =
            clouds::tools::renderCpuReference(textures(), u, slabSettings(sigma, step), {}, 1);
        const double expected = std::exp(-double(sigma) * path);
        EXPECT_NEAR(frame.radiance[0].a, expected, 2e-5 + 1e-5 * expected)
            << "tau " << tau << " pitch " << pitch << " step " << step;
      }
    }
  }
}

// A ray whose steps would run out before the end of its segment (a long ray through a tall
// layer towards the horizon) stretches them to reach it: the far clouds are marched coarsely
// rather than left out. A homogeneous slab's steps are exact at any length, so 8 steps of the
// 50 m asked for must still give Beer-Lambert over the whole path (which they cover 1/12 of).
TEST(CloudModelCpu, ASmallStepBudgetStillCoversTheWholeLayer) {
  const VkExtent2D extent{1, 1};
  const double pitch = 30.0;
  clouds::Settings s = slabSettings(1.0f, 50.0f);
  s.maxViewSteps = 8;
  CloudUniforms u = uniformsFor(s, 300.0, pitch, extent);
  const vec3 dir = pixelRayDirection(vec2(0.5f, 0.5f), vec2(1.0f, 1.0f), u);
  const vec2 segment = layerSegment(300.0f, dir.y, u);
  const double path = double(segment.y) - double(segment.x);
  ASSERT_GT(path, 12.0 * 8.0 * 50.0);
  s.extinctionPerMetre = static_cast<float>(1.0 / path);  // optical depth 1 along the ray
  u = uniformsFor(s, 300.0, pitch, extent);
  u.flags |= kFlagHomogeneous;
  const auto frame = clouds::tools::renderCpuReference(textures(), u, s, {}, 1);
  EXPECT_NEAR(frame.radiance[0].a, std::exp(-1.0), 1e-4);
}

// The march from inside the layer takes its short steps near the camera on top of the sample
// budget: 9 of them (from a sixteenth of the 50 m step, half the distance, to 100 m), then the
// 8 steps of the budget, stretched to reach the top of the layer (Beer-Lambert over the whole
// path). From below the layer there are none.
TEST(CloudModelCpu, NearTheCameraStepsComeOnTopOfTheBudget) {
  const VkExtent2D extent{1, 1};
  clouds::Settings s = slabSettings(1.0f, 50.0f);
  s.maxViewSteps = 8;
  MarchOptions options{};
  options.lightSteps = 1;
  for (const double altitude : {2500.0, 300.0}) {
    CloudUniforms u = uniformsFor(s, altitude, 30.0, extent);
    const vec3 dir = pixelRayDirection(vec2(0.5f, 0.5f), vec2(1.0f, 1.0f), u);
    const vec2 segment = layerSegment(float(altitude), dir.y, u);
    const double path = double(segment.y) - double(segment.x);
    ASSERT_GT(path, 1000.0);
    clouds::Settings slab = s;
    slab.extinctionPerMetre = static_cast<float>(1.0 / path);  // optical depth 1 along the ray
    u = uniformsFor(slab, altitude, 30.0, extent);
    u.flags |= kFlagHomogeneous;
    const MarchResult r = marchClouds(dir, kInfiniteDistance, 0.5f, vec3(0.5f), u, options);
    const bool inside = altitude > 1500.0;
    EXPECT_EQ(r.viewSamples, inside ? 8.0f + 9.0f : 8.0f) << "altitude " << altitude;
    EXPECT_NEAR(r.transmittance, std::exp(-1.0), 1e-4) << "altitude " << altitude;
  }
}

// The near/far split (Settings::nearFieldMetres): the near field's pass marches the ray up to
// the split, the tiles' march from it on, and the one laid over the other (layNearOverFar(), as
// upsample.comp does) is the whole ray: inside a homogeneous slab, Beer-Lambert over each part
// and over the whole, and the whole march's radiance.
TEST(CloudModelCpu, TheNearFieldLaidOverTheFarPartIsTheWholeRay) {
  const VkExtent2D extent{1, 1};
  const double altitude = 2500.0;
  clouds::Settings s = slabSettings(1.0f, 20.0f);
  CloudUniforms u = uniformsFor(s, altitude, 30.0, extent);
  const vec3 dir = pixelRayDirection(vec2(0.5f, 0.5f), vec2(1.0f, 1.0f), u);
  const vec2 segment = layerSegment(float(altitude), dir.y, u);
  const double path = double(segment.y) - double(segment.x);
  ASSERT_GT(path, 1000.0);
  s.extinctionPerMetre = static_cast<float>(2.0 / path);  // optical depth 2 along the ray
  u = uniformsFor(s, altitude, 30.0, extent);
  u.flags |= kFlagHomogeneous;
  MarchOptions options{};
  options.lightSteps = 4;
  const MarchResult whole = marchClouds(dir, kInfiniteDistance, 0.5f, vec3(0.5f), u, options);

  const float split = 200.0f;
  u.nearFieldMetres = split;
  const MarchResult far = marchClouds(dir, kInfiniteDistance, 0.5f, vec3(0.5f), u, options);
  options.nearField = 1u;
  const MarchResult near = marchClouds(dir, kInfiniteDistance, 0.5f, vec3(0.5f), u, options);
  const double sigma = s.extinctionPerMetre;
  EXPECT_NEAR(near.transmittance, std::exp(-sigma * split), 1e-4);
  EXPECT_NEAR(far.transmittance, std::exp(-sigma * (path - split)), 1e-4);
  EXPECT_GE(far.frontDepth, split);
  EXPECT_LE(near.weightedDepth, split);

  vec4 laid(far.radiance, far.transmittance);
  vec2 laidDepth(far.frontDepth, far.weightedDepth);
  layNearOverFar(vec4(near.radiance, near.transmittance), vec2(near.frontDepth, near.weightedDepth),
                 laid, laidDepth);
  EXPECT_NEAR(laid.a, std::exp(-2.0), 1e-4);
  EXPECT_NEAR(laid.a, whole.transmittance, 1e-4);
  ASSERT_GT(whole.radiance.g, 0.0f);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(laid[c], whole.radiance[c], 0.01 * whole.radiance[c]) << "channel " << c;
  }
  EXPECT_FLOAT_EQ(laidDepth.x, near.frontDepth);
  EXPECT_NEAR(laidDepth.y, whole.weightedDepth, 0.01 * whole.weightedDepth);
}

// Single scattering from a homogeneous slab seen straight up with the sun at elevation e:
// L = E p albedo sigma e^{-sigma D / mu} int_0^D e^{-sigma s (1 - 1/mu)} ds.
double slabSingleScattering(double sigma, double thickness, double mu, double phase) {
  const double k = sigma * (1.0 - 1.0 / mu);
  return phase * sigma * std::exp(-sigma * thickness / mu) * std::expm1(-k * thickness) / -k;
}

// The sunlit slab of the single-scattering tests: 2500 m thick, optical depth 0.4 vertically,
// the sun 50 degrees up, seen straight up from below; the light march spans the sun's whole
// path through it along the sun itself (no cone), albedo 1.
constexpr double kSunlitSlabThickness = 2500.0;
constexpr float kSunlitSlabSigma = 0.4f / 2500.0f;
const double kSunlitSlabElevation = glm::radians(50.0);
const glm::vec3 kSunlitSlabSun(0.0f, static_cast<float>(std::sin(kSunlitSlabElevation)),
                               -static_cast<float>(std::cos(kSunlitSlabElevation)));

clouds::Settings sunlitSlabSettings(float stepMetres) {
  clouds::Settings s = slabSettings(kSunlitSlabSigma, stepMetres);
  s.lightConeMetres =
      static_cast<float>(kSunlitSlabThickness / std::sin(kSunlitSlabElevation) * 1.0001);
  s.lightConeSpread = 0.0f;
  s.albedo = 1.0f;
  return s;
}

CloudUniforms sunlitSlabUniforms(const clouds::Settings& s) {
  CloudUniforms u = uniformsFor(s, 300.0, 90.0, VkExtent2D{1, 1}, kSunlitSlabSun);
  u.flags |= kFlagHomogeneous;
  return u;
}

TEST(CloudModelCpu, SlabRadianceConvergesAsStepsDouble) {
  const glm::vec3 sun = kSunlitSlabSun;
  const double elevation = kSunlitSlabElevation;
  const double thickness = kSunlitSlabThickness;
  const float sigma = kSunlitSlabSigma;
  std::vector<double> errors;
  for (std::uint32_t doubling = 0; doubling < 6; ++doubling) {
    clouds::Settings s = sunlitSlabSettings(500.0f / float(1u << doubling));
    s.lightSteps = 2u << doubling;
    const CloudUniforms u = sunlitSlabUniforms(s);
    const auto frame = clouds::tools::renderCpuReference(textures(), u, s, {}, 1);
    const vec3 dir = pixelRayDirection(vec2(0.5f, 0.5f), vec2(1.0f, 1.0f), u);
    const double phase =
        dualLobePhase(dot(dir, sun), s.phaseForwardG, s.phaseBackwardG, s.phaseBackwardWeight);
    const double expected = slabSingleScattering(sigma, thickness, std::sin(elevation), phase);
    errors.push_back(std::abs(frame.radiance[0].r - expected) / expected);
  }
  // The light march cuts the slab's top at a step boundary, so the error is first order and
  // not monotonic step to step; over five doublings it must still fall by an order of
  // magnitude, and end small.
  std::string trace;
  for (double e : errors) trace += std::to_string(e) + " ";
  EXPECT_LT(errors.back(), errors.front() / 10.0) << trace;
  EXPECT_LT(errors.back(), 2e-3) << trace;
}

// Light reuse (MarchOptions::lightReuse): of two cloudy samples in a row, the second takes the
// first's optical depth towards the sun. Through the slab, where that depth changes smoothly,
// about half the light samples give the same transmittance and a single scattering that
// differs by the step's share of the sun's path: a first-order error, halving with the step.
TEST(CloudModelCpu, LightReuseHalvesTheLightSamplesForAFirstOrderError) {
  const std::uint32_t lightSteps = 8;
  std::vector<double> differences;
  std::string trace;
  for (float step : {100.0f, 50.0f, 25.0f}) {
    const CloudUniforms u = sunlitSlabUniforms(sunlitSlabSettings(step));
    const vec3 dir = pixelRayDirection(vec2(0.5f, 0.5f), vec2(1.0f, 1.0f), u);
    MarchOptions options{};
    options.lightSteps = lightSteps;
    const MarchResult own = marchClouds(dir, kInfiniteDistance, 0.5f, vec3(0.5f), u, options);
    options.lightReuse = 1u;
    const MarchResult reused = marchClouds(dir, kInfiniteDistance, 0.5f, vec3(0.5f), u, options);
    // Every other sample marches its own (the first of the run included): half, rounded up.
    EXPECT_NEAR(reused.lightSamples, own.lightSamples / 2.0f, float(lightSteps)) << step;
    EXPECT_EQ(reused.transmittance, own.transmittance) << step;
    differences.push_back(std::abs(reused.radiance.r - own.radiance.r) / own.radiance.r);
    trace += std::to_string(differences.back()) + " ";
  }
  EXPECT_GT(differences.front(), 0.0) << trace;  // the reuse took place
  EXPECT_LT(differences.front(), 0.02) << trace;
  EXPECT_LT(differences.back(), differences.front() / 3.0) << trace;  // 4x finer steps
}

// The first cloudy sample of a run has no optical depth to reuse, even on a step where it
// would. With cheap sampling and a budget of 2, the coarse sample that finds the slab (step 0)
// is taken again as a fine one on step 1, the ray's only cloudy sample: with reuse or without,
// the same light.
TEST(CloudModelCpu, LightReuseNeverReusesAcrossEmptySpace) {
  clouds::Settings s = sunlitSlabSettings(100.0f);
  s.maxViewSteps = 2;
  const CloudUniforms u = sunlitSlabUniforms(s);
  const vec3 dir = pixelRayDirection(vec2(0.5f, 0.5f), vec2(1.0f, 1.0f), u);
  MarchOptions options{};
  options.cheapSampling = 1u;
  options.lightSteps = 4;
  const MarchResult own = marchClouds(dir, kInfiniteDistance, 0.5f, vec3(0.5f), u, options);
  options.lightReuse = 1u;
  const MarchResult reused = marchClouds(dir, kInfiniteDistance, 0.5f, vec3(0.5f), u, options);
  ASSERT_EQ(own.viewSamples, 2.0f);
  EXPECT_EQ(reused.lightSamples, own.lightSamples);
  EXPECT_EQ(reused.radiance.r, own.radiance.r);
}

TEST(CloudModelCpu, WhiteFurnaceConservesEnergy) {
  const VkExtent2D extent{16, 12};
  for (float density : {0.0f, 0.01f, 1.0f, 100.0f, 1e4f, 1e6f}) {
    for (std::uint32_t steps : {4u, 64u, 512u}) {
      clouds::Settings s;
      s.densityMultiplier = density;
      s.maxViewSteps = steps;
      s.albedo = 1.0f;
      s.sunStrength = 0.0f;
      s.inScatterStrength = 0.0f;
      s.ambientOcclusionStrength = 0.0f;
      s.ambientStrength = 1.0f;
      s.coverage = 0.8f;
      clouds::tools::CloudView view;
      clouds::FrameInputs in;
      view.position = {0.0, 2000.0, 0.0};  // inside the layer
      view.pitchDegrees = 5.0;
      in.view = clouds::tools::viewMatrix(view);
      in.projection = clouds::tools::projectionMatrix(view, extent);
      in.cameraPosition = view.position;
      in.ambientTop = glm::vec3(1.0f);
      in.ambientBottom = glm::vec3(1.0f);
      clouds::detail::UniformContext context;
      context.traceExtent = extent;
      context.fullExtent = extent;
      const CloudUniforms u = clouds::detail::buildUniforms(in, s, context);
      const auto frame = clouds::tools::renderCpuReference(textures(), u, s, {}, 2);
      for (const auto& p : frame.radiance) {
        for (int c = 0; c < 3; ++c) {
          ASSERT_NEAR(p[c] + p.a * 1.0f, 1.0f, 1e-4f)
              << "density " << density << " steps " << steps << " T " << p.a;
        }
      }
    }
  }
}

}  // namespace

// The skew's lean (skewLean(), cloud_march.h) is the integral of the wind's direction over
// height: without shear a straight lean of skewMetres x height downwind; with shear, at each
// height its slope is the wind's direction turned by that height's share of the shear
// (counter-clockwise seen from above: +x turns towards -z), so the top leans the way the upper
// wind blows, and the curved column is no longer than the straight one.
TEST(CloudModelCpu, TheSkewLeansAlongTheWindAsItTurnsWithHeight) {
  using clouds::shader::skewLean;
  clouds::shader::CloudUniforms u{};
  u.windDirection = glm::vec2(1.0f, 0.0f);
  u.skewMetres = 1000.0f;
  u.windShearRadians = 0.0f;
  EXPECT_NEAR(skewLean(0.5f, u).x, 500.0f, 1e-3f);
  EXPECT_NEAR(skewLean(0.5f, u).y, 0.0f, 1e-3f);
  EXPECT_NEAR(skewLean(2.0f, u).x, 1000.0f, 1e-3f) << "the lean stops at the layer's top";
  for (const float shear : {glm::half_pi<float>(), -0.7f, 2e-4f, 3.0f}) {
    u.windShearRadians = shear;
    for (const float h : {0.1f, 0.5f, 0.95f}) {
      const float dh = 1e-3f;
      const glm::vec2 slope = (skewLean(h + dh, u) - skewLean(h - dh, u)) / (2.0f * dh);
      const float turned = shear * h;
      const glm::vec2 wind(std::cos(turned), -std::sin(turned));  // +x turned counter-clockwise
      EXPECT_NEAR(slope.x, u.skewMetres * wind.x, 0.5f) << "shear " << shear << " at " << h;
      EXPECT_NEAR(slope.y, u.skewMetres * wind.y, 0.5f) << "shear " << shear << " at " << h;
      EXPECT_LE(glm::length(skewLean(h, u)), u.skewMetres * h + 1e-2f);
    }
  }
  // A quarter turn: the top sits 2/pi of the skew along the base wind and as far across.
  u.windShearRadians = glm::half_pi<float>();
  EXPECT_NEAR(skewLean(1.0f, u).x, 1000.0f * 2.0f / glm::pi<float>(), 0.1f);
  EXPECT_NEAR(skewLean(1.0f, u).y, -1000.0f * 2.0f / glm::pi<float>(), 0.1f);
}
