// The sky light (Settings::skyLight, Outputs::skyLight, Context::skyLighting()): the host's sky
// with the clouds in it. Under a clear sky the map is the host's sky and its measures are the
// brute-force integrals of it; under an overcast its upper half is the host's sky through the
// clouds the CPU reference marches towards each texel, and its irradiance (pi x
// upperIrradianceOverPi) the CPU's integral of that, greyer than the clear sky's and, without the
// sun, darker than the clear sky and the sun together; the ground below is lit by it; each frame
// marches a quarter of its clouds; what cloud bases see below them is lit by the last frame's
// map (darker under an overcast, as before under a clear sky); for an exposure meter, the sun
// at the camera is the shadow map's there; hard cases stay finite; without the host's sky it is
// refused by name, and off it costs no pass and no memory. Validation-clean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cloud_gpu_fixture.h"
#include "cloud_harness.h"
#include "cloud_lighting.h"
#include "cpu_reference.h"
#include "engine/gfx/upload.h"
#include "gpu_test.h"

namespace {

using clouds::tools::CloudView;
using clouds::tools::SkyLightImage;

using SkyLight = test::SharedHarnessTest<64, 36>;

constexpr VkExtent2D kExtent{64, 36};
constexpr std::uint32_t kWidth = clouds::kSkyLightExtent.width;
constexpr std::uint32_t kHeight = clouds::kSkyLightExtent.height;
constexpr double kPi = 3.14159265358979323846;

// A host sky image laid out as the sky light's map (texel centres on the same directions).
class HostSky {
 public:
  HostSky(engine::gfx::Device& device, std::vector<glm::vec4> texels)
      : texels_(std::move(texels)),
        image_(device,
               engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                      VK_FORMAT_R32G32B32A32_SFLOAT,
                                      {kWidth, kHeight, 1},
                                      1,
                                      1,
                                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                      "host sky"}) {
    engine::gfx::uploadToImage(device, image_, std::as_bytes(std::span(texels_)),
                               engine::gfx::ImageState{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                       VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                                       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  }
  VkImageView view() const { return image_.view(); }
  glm::dvec3 at(std::uint32_t x, std::uint32_t y) const {
    return glm::dvec3(texels_[std::size_t{y} * kWidth + x]);
  }

 private:
  std::vector<glm::vec4> texels_;
  engine::gfx::Image image_;
};

double elevationOf(std::uint32_t y) {
  return kPi * (0.5 - (y + 0.5) / kHeight);
}

// A clear sky: a blue zenith over a paler horizon, a grey ground below.
std::vector<glm::vec4> gradientSky() {
  std::vector<glm::vec4> texels;
  for (std::uint32_t y = 0; y < kHeight; ++y) {
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const double e = elevationOf(y);
      const glm::vec3 zenith(0.15f, 0.3f, 0.8f);
      const glm::vec3 horizon(0.6f, 0.7f, 0.9f);
      const float t = static_cast<float>(std::sqrt(std::max(std::sin(e), 0.0)));
      // A little azimuthal variation, so that a texel read in the wrong column shows.
      const float glow = 1.0f + 0.2f * static_cast<float>(std::cos(2.0 * kPi * (x + 0.5) / kWidth));
      texels.emplace_back(
          e >= 0.0 ? glm::mix(horizon, zenith, t) * glow : glm::vec3(0.12f, 0.11f, 0.1f), 1.0f);
    }
  }
  return texels;
}

// One sky radiance everywhere: the clouds' ambient (sky_ambient.comp) is then that radiance
// exactly, which the CPU reference's uniforms can be given.
const glm::vec3 kUniformSky(0.35f, 0.5f, 0.85f);
std::vector<glm::vec4> uniformSky() {
  return std::vector<glm::vec4>(std::size_t{kWidth} * kHeight, glm::vec4(kUniformSky, 1.0f));
}

// The measures of a map, integrated on the CPU in double precision by solid angle
// (cos(elevation) per texel of an equirectangular map), as Context::skyLighting() defines them.
struct Integrals {
  glm::dvec3 upperIrradianceOverPi{0.0};
  glm::dvec3 zenith{0.0};
  glm::dvec3 horizon{0.0};
  glm::dvec3 lower{0.0};
};

template <typename RadianceAt>
Integrals integrate(const RadianceAt& radianceAt) {
  glm::dvec4 upper(0.0), zenith(0.0), horizon(0.0), lower(0.0);
  for (std::uint32_t y = 0; y < kHeight; ++y) {
    const double e = elevationOf(y);
    const double solidAngle = std::cos(e);
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const glm::dvec4 l(radianceAt(x, y), 1.0);
      if (e >= 0.0) upper += l * solidAngle * std::sin(e);
      if (e >= kPi / 3.0) zenith += l * solidAngle;
      if (e >= 0.0 && e <= kPi / 18.0) horizon += l * solidAngle;
      if (e < 0.0) lower += l * solidAngle;
    }
  }
  return {glm::dvec3(upper) / upper.w, glm::dvec3(zenith) / zenith.w,
          glm::dvec3(horizon) / horizon.w, glm::dvec3(lower) / lower.w};
}

double luminance(const glm::dvec3& c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

void expectClose(const glm::vec3& gpu, const glm::dvec3& cpu, double tolerance, const char* what) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(gpu[c], cpu[c], tolerance * std::max(std::abs(cpu[c]), 1e-6))
        << what << " channel " << c;
  }
}

clouds::Settings skyLit(clouds::Settings s) {
  s.skyLight = true;
  return s;
}

clouds::Settings overcast() {
  clouds::Settings s;
  s.coverage = 1.0f;
  s.cloudType = 0.3f;
  s.densityVariation = 0.0f;
  return clouds::tools::singleFrame(skyLit(clouds::settingsFor(clouds::Quality::Medium, s)));
}

CloudView groundView(VkImageView sky) {
  CloudView view = test::cumulusView();
  view.skyView = sky;
  view.sunElevationDegrees = 40.0;
  view.ambientTop = kUniformSky;
  view.ambientBottom = kUniformSky;
  return view;
}

TEST_F(SkyLight, AClearSkyIsTheHostsSkyAndItsMeasuresItsIntegrals) {
  const HostSky host(device(), gradientSky());
  clouds::Settings s = skyLit(clouds::Settings{});
  s.coverage = 0.0f;  // nothing to march: the sky is the host's alone
  harness().cut();
  harness().render(groundView(host.view()), s, kExtent);
  const SkyLightImage map = harness().readSkyLight();
  ASSERT_EQ(map.width, kWidth);
  ASSERT_TRUE(map.measures.valid);
  for (std::uint32_t y = 0; y < kHeight; ++y) {
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const glm::dvec3 expected = host.at(x, y);
      for (int c = 0; c < 3; ++c) {
        // RGBA16F: 11 bits of mantissa.
        ASSERT_NEAR(map.at(x, y)[c], expected[c], 1e-3 * expected[c]) << x << ", " << y;
      }
    }
  }
  const Integrals cpu = integrate([&](std::uint32_t x, std::uint32_t y) { return host.at(x, y); });
  std::printf("clear sky: mean upper %.5f %.5f %.5f (CPU %.5f %.5f %.5f)\n",
              map.measures.upperIrradianceOverPi.r, map.measures.upperIrradianceOverPi.g,
              map.measures.upperIrradianceOverPi.b, cpu.upperIrradianceOverPi.r,
              cpu.upperIrradianceOverPi.g, cpu.upperIrradianceOverPi.b);
  expectClose(map.measures.upperIrradianceOverPi, cpu.upperIrradianceOverPi, 1e-4, "mean upper");
  expectClose(map.measures.clearIrradianceOverPi, cpu.upperIrradianceOverPi, 1e-4, "clear upper");
  expectClose(map.measures.zenith, cpu.zenith, 1e-4, "zenith");
  expectClose(map.measures.horizon, cpu.horizon, 1e-4, "horizon");
  expectClose(map.measures.lower, cpu.lower, 1e-4, "lower");
}

TEST_F(SkyLight, AnOvercastLightsAsTheCpuReferenceDarkerAndGreyer) {
  const HostSky host(device(), uniformSky());
  const clouds::Settings s = overcast();
  const CloudView view = groundView(host.view());
  harness().cut();
  harness().render(view, s, kExtent);
  const SkyLightImage map = harness().readSkyLight();
  ASSERT_TRUE(map.measures.valid);
  // The CPU reference marches each texel's ray with the frame's uniforms, whose ambient the sky
  // ambient pass set to the uniform sky: the view's own.
  const clouds::tools::CpuTextures textures = clouds::tools::readTextures(harness());
  const std::vector<glm::vec4> clouds =
      clouds::tools::cpuSkyLightClouds(textures, impl().lastUniforms(), s);
  const auto cpuRadiance = [&](std::uint32_t x, std::uint32_t y) {
    if (y >= kHeight / 2) return host.at(x, y);
    const glm::dvec4 c(clouds[std::size_t{y} * kWidth + x]);
    return host.at(x, y) * c.a + glm::dvec3(c);
  };
  const Integrals cpu = integrate(cpuRadiance);
  const Integrals gpu =
      integrate([&](std::uint32_t x, std::uint32_t y) { return glm::dvec3(map.at(x, y)); });
  double worst = 0.0;
  double opacity = 0.0;
  for (std::uint32_t y = 0; y < kHeight / 2; ++y) {
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      worst = std::max(
          worst, std::abs(luminance(glm::dvec3(map.at(x, y))) - luminance(cpuRadiance(x, y))) /
                     luminance(cpuRadiance(x, y)));
      opacity += 1.0 - double(clouds[std::size_t{y} * kWidth + x].a);
    }
  }
  opacity /= double(kWidth * kHeight / 2);
  const glm::vec3 sky = map.measures.upperIrradianceOverPi;
  const glm::vec3 clear = map.measures.clearIrradianceOverPi;
  std::printf(
      "overcast: opacity %.3f; irradiance / pi %.4f %.4f %.4f (CPU %.4f %.4f %.4f), clear %.4f "
      "%.4f %.4f; worst texel %.4f of the CPU's\n",
      opacity, sky.r, sky.g, sky.b, cpu.upperIrradianceOverPi.r, cpu.upperIrradianceOverPi.g,
      cpu.upperIrradianceOverPi.b, clear.r, clear.g, clear.b, worst);
  ASSERT_GT(opacity, 0.9) << "the view must be overcast";
  // The map's own reduction against the CPU's integral of the same texels, then against the
  // CPU reference's clouds (the march's float arithmetic on two devices).
  expectClose(sky, gpu.upperIrradianceOverPi, 1e-3, "the map's mean upper");
  expectClose(sky, cpu.upperIrradianceOverPi, 0.02, "mean upper against the CPU reference");
  expectClose(map.measures.zenith, cpu.zenith, 0.02, "zenith against the CPU reference");
  expectClose(map.measures.horizon, cpu.horizon, 0.03, "horizon against the CPU reference");
  EXPECT_LT(worst, 0.1) << "a texel far from the CPU reference's";
  expectClose(clear, glm::dvec3(kUniformSky), 1e-4, "the clear sky under it");
  // Greyer: blue no longer dominating red. Darker where it counts: the overcast itself may be
  // brighter than the blue sky it hides (sunlight scattered down through it, as under a bright
  // grey deck), but what lights the ground, its irradiance with the sun hidden, is less than
  // half the clear sky's plus the sun's (the next test shows the sun hidden from the ground).
  EXPECT_LT(sky.b / sky.r, 0.8 * clear.b / clear.r);
  const double sunOnGround =
      luminance(glm::dvec3(view.sunIlluminance)) * std::sin(glm::radians(view.sunElevationDegrees));
  const double overcastIrradiance = kPi * luminance(glm::dvec3(sky));
  const double clearIrradiance = kPi * luminance(glm::dvec3(clear)) + sunOnGround;
  std::printf("irradiance on the ground (luminance): overcast %.3f, clear %.3f\n",
              overcastIrradiance, clearIrradiance);
  EXPECT_LT(overcastIrradiance, 0.5 * clearIrradiance);
}

// With the ground's albedo, the map's ground (more than 10 degrees below the horizon) is the
// albedo lit by the map's own sky and by the sun on the share of the ground in it: under a clear
// sky all of the sun, under an overcast little of it.
TEST_F(SkyLight, TheGroundBelowIsLitByTheSkyAbove) {
  const HostSky host(device(), uniformSky());
  const glm::vec3 albedo(0.3f, 0.25f, 0.2f);
  for (const bool cloudy : {false, true}) {
    clouds::Settings s = overcast();
    if (!cloudy) s.coverage = 0.0f;
    CloudView view = groundView(host.view());
    view.groundAlbedo = albedo;
    harness().cut();
    harness().render(view, s, kExtent);
    const SkyLightImage map = harness().readSkyLight();
    ASSERT_TRUE(map.measures.valid);
    const glm::dvec3 sky(map.measures.upperIrradianceOverPi);
    const double sunUp = std::sin(glm::radians(view.sunElevationDegrees));
    const glm::dvec3 sun(view.sunIlluminance);
    const glm::vec4 ground = map.at(5, kHeight - 3);
    // Its sunlit share, from its red channel: ground = albedo (sun sunUp share + pi sky) / pi.
    const double share = (kPi * ground.r / albedo.r - kPi * sky.r) / (sun.r * sunUp);
    std::printf("%s: ground %.4f %.4f %.4f, its sunlit share %.3f\n", cloudy ? "overcast" : "clear",
                ground.r, ground.g, ground.b, share);
    for (std::uint32_t y = kHeight / 2; y < kHeight; ++y) {
      if (elevationOf(y) >= -kPi / 18.0) continue;
      for (std::uint32_t x = 0; x < kWidth; ++x) ASSERT_EQ(map.at(x, y), ground) << x << ", " << y;
    }
    for (int c = 0; c < 3; ++c) {
      const double expected = albedo[c] * (sun[c] * sunUp * share + kPi * sky[c]) / kPi;
      EXPECT_NEAR(ground[c], expected, 2e-3 * expected) << "channel " << c;
    }
    if (cloudy) {
      EXPECT_LT(share, 0.2) << "the overcast hides the sun from the ground";
    } else {
      EXPECT_NEAR(share, 1.0, 2e-3) << "a clear sky hides nothing";
    }
  }
}

// After a frame that marched every texel, each frame marches one texel in each 2 x 2 block of
// the upper half, in turn: the others keep what they had, however the clouds moved.
TEST_F(SkyLight, EachFrameMarchesAQuarterOfTheClouds) {
  const HostSky host(device(), uniformSky());
  clouds::Settings s = skyLit(clouds::settingsFor(clouds::Quality::Medium, {}));
  s.coverage = 0.6f;
  s.windSpeedMetresPerSecond = 40.0f;
  CloudView view = groundView(host.view());
  harness().cut();
  harness().render(view, s, kExtent);
  SkyLightImage before = harness().readSkyLight();
  for (std::uint32_t frame = 1; frame <= 4; ++frame) {
    view.timeSeconds += 20.0;  // 800 m of wind: every cloud moved
    harness().render(view, s, kExtent);
    const SkyLightImage after = harness().readSkyLight();
    const glm::uvec2 due(frame % 2, (frame / 2) % 2);  // the round after the whole frame's
    std::size_t changed = 0;
    std::size_t dueTexels = 0;
    for (std::uint32_t y = 0; y < kHeight / 2; ++y) {
      for (std::uint32_t x = 0; x < kWidth; ++x) {
        if (x % 2 == due.x && y % 2 == due.y) {
          ++dueTexels;
          if (after.at(x, y) != before.at(x, y)) ++changed;
        } else {
          ASSERT_EQ(after.at(x, y), before.at(x, y)) << "frame " << frame << ": " << x << ", " << y;
        }
      }
    }
    std::printf("frame %u: %zu of its %zu texels changed\n", frame, changed, dueTexels);
    EXPECT_GT(changed, dueTexels / 4) << "frame " << frame;
    before = after;
  }
}

// The sky light is the ground's: a camera inside or above the layer gets the sky as seen from
// under the layer straight below it (10 m under its base), as a camera there does, not the clear
// sky above the layer. (A camera lower down sees the layer from further away, with the march's
// longer steps and other samples: 40 m lower its irradiance differs by 1.1%, 1.2 km by 3%.)
TEST_F(SkyLight, AboveTheLayerItIsTheSkyBelowIt) {
  const HostSky host(device(), uniformSky());
  clouds::Settings s = skyLit(clouds::settingsFor(clouds::Quality::Medium, {}));
  s.coverage = 0.6f;
  const double under = s.layerBottomMetres - 10.0;
  glm::vec3 below{0.0f};
  for (const double altitude : {under, 2500.0, 9000.0}) {
    CloudView view = groundView(host.view());
    view.position.y = altitude;
    harness().cut();
    harness().render(view, s, kExtent);
    const glm::vec3 sky = harness().readSkyLight().measures.upperIrradianceOverPi;
    std::printf("camera at %.0f m: irradiance / pi %.4f %.4f %.4f (clear %.4f %.4f %.4f)\n",
                altitude, sky.r, sky.g, sky.b, kUniformSky.r, kUniformSky.g, kUniformSky.b);
    if (altitude == under) {
      below = sky;
      ASSERT_LT(sky.b / sky.r, 0.9f * kUniformSky.b / kUniformSky.r) << "clouds in the sky";
      continue;
    }
    expectClose(sky, glm::dvec3(below), 1e-4, "the sky from under the layer");
  }
}

// For an exposure meter at the camera: the sun's transmittance there is the shadow map's (the
// lookup every receiver makes), nothing under a clear sky, above the layer or without a map; the
// ground around is in the overcast's shade; and the altitudes the map holds for are where its
// rays start and the layer's top.
TEST_F(SkyLight, TheSunAtTheCameraIsTheShadowMapsThere) {
  const HostSky host(device(), uniformSky());
  const clouds::Settings cloudy = overcast();
  ASSERT_GT(cloudy.shadowCascades, 0u);
  std::vector<float> atCamera;
  std::vector<double> altitudes = {300.0};
  for (std::size_t run = 0; run < 3; ++run) {
    const double altitude = altitudes[run];
    CloudView view = groundView(host.view());
    view.groundAlbedo = glm::vec3(0.3f);  // the harness makes the shadow map for the ground's light
    view.position.y = altitude;
    harness().cut();
    harness().render(view, cloudy, kExtent);
    const clouds::SkyLighting measures = harness().readSkyLight().measures;
    const clouds::tools::ShadowMapImage map = harness().readShadowMap();
    ASSERT_FALSE(map.texels.empty());
    const float expected = map.transmittance(glm::vec3(0.0f));
    std::printf("camera at %.0f m: sun at the camera %.5f (the shadow map's %.5f)\n", altitude,
                measures.sunTransmittanceAtCamera, expected);
    EXPECT_NEAR(measures.sunTransmittanceAtCamera, expected, 2e-3) << altitude;
    // The ground around: the mean of the finest cascade, as the ground texels' share (tested
    // with them in TheGroundBelowIsLitByTheSkyAbove): all of it in the overcast's shade.
    EXPECT_LT(measures.sunlitShareAround, 0.05f) << altitude;
    atCamera.push_back(measures.sunTransmittanceAtCamera);
    if (run == 0) {
      // Next, inside the clouds where the sun is half hidden (the map's lookup, up from here),
      // then above the layer.
      double up = 0.0;
      while (up < 8000.0 && map.transmittance(glm::vec3(0.0f, float(up), 0.0f)) < 0.5f) up += 20.0;
      altitudes.push_back(altitude + up);
      altitudes.push_back(9000.0);
    }
    EXPECT_FLOAT_EQ(measures.seenFromAltitudeMetres,
                    float(std::min(altitude, cloudy.layerBottomMetres - 10.0)));
    EXPECT_FLOAT_EQ(measures.coverTopMetres, float(cloudy.layerTopMetres));
  }
  EXPECT_LT(atCamera[0], 0.05f) << "under the overcast, in its shade";
  EXPECT_GT(atCamera[1], atCamera[0]) << "in the clouds, some of them towards the sun";
  EXPECT_LT(atCamera[1], atCamera[2]);
  EXPECT_NEAR(atCamera[2], 1.0f, 1e-3f) << "above the layer, in the sun";
  clouds::Settings clear = cloudy;
  clear.coverage = 0.0f;
  clouds::Settings unmapped = cloudy;
  unmapped.shadowCascades = 0;
  for (const clouds::Settings& s : {clear, unmapped}) {
    CloudView view = groundView(host.view());
    view.groundAlbedo = glm::vec3(0.3f);
    harness().cut();
    harness().render(view, s, kExtent);
    const clouds::SkyLighting measures = harness().readSkyLight().measures;
    EXPECT_EQ(measures.sunTransmittanceAtCamera, 1.0f)
        << (s.coverage == 0.0f ? "a clear sky" : "no shadow map");
    EXPECT_EQ(measures.sunlitShareAround, 1.0f);
  }
}

// What cloud bases see below them (ambientBottom): with the sky light, the ground lit by the
// last frame's map (its irradiance, and the sun on the share of the ground in it) and the map's
// horizon band, in place of the clear sky's. `first`: the last frame's map; `now`: this frame's
// (the share in the sun is this frame's).
glm::vec3 bottomLitBy(const glm::vec3& horizon, const glm::vec3& sky, const glm::vec3& albedo,
                      const clouds::shader::CloudUniforms& u, const SkyLightImage& now) {
  return clouds::shader::groundLitBaseRadiance(horizon, sky, albedo, u.sunIlluminance,
                                               u.sunDirection.y, now.measures.sunlitShareAround);
}

// Under an overcast, the ground is lit by the overcast, not by the clear sky above it: the next
// frame's march is the CPU reference's with its bases lit so, and not the CPU's with the clear
// sky's light (what the clouds had without the sky light). That light is greyer; it need not be
// darker: a sunlit deck may send more light down than the blue sky it hides (the sun itself is
// hidden from the ground in both).
TEST_F(SkyLight, UnderAnOvercastTheBasesSeeTheGroundTheOvercastLights) {
  const HostSky host(device(), uniformSky());
  const glm::vec3 albedo(0.3f, 0.25f, 0.2f);
  CloudView view = groundView(host.view());
  view.groundAlbedo = albedo;
  view.pitchDegrees = 35.0;  // the bases fill the view
  const clouds::Settings s = overcast();
  harness().cut();
  harness().render(view, s, kExtent);
  const SkyLightImage first = harness().readSkyLight();
  const clouds::tools::CloudFrame gpu = harness().render(view, s, kExtent);
  const SkyLightImage now = harness().readSkyLight();
  ASSERT_TRUE(first.measures.valid && now.measures.valid);
  clouds::shader::CloudUniforms u = impl().lastUniforms();
  u.ambientTop = kUniformSky;  // the sky ambient's, from the uniform sky
  const glm::vec3 covered =
      bottomLitBy(first.measures.horizon, first.measures.upperIrradianceOverPi, albedo, u, now);
  const glm::vec3 clear = bottomLitBy(kUniformSky, kUniformSky, albedo, u, now);
  const clouds::tools::CpuTextures textures = clouds::tools::readTextures(harness());
  const auto cpuWithBases = [&](const glm::vec3& bottom) {
    clouds::shader::CloudUniforms lit = u;
    lit.ambientBottom = bottom;
    return clouds::tools::renderCpuReference(textures, lit, s, harness().lastDepth());
  };
  const clouds::tools::CloudFrame cpuCovered = cpuWithBases(covered);
  const clouds::tools::CloudFrame cpuClear = cpuWithBases(clear);
  float peak = 1.0f;
  for (const glm::vec4& p : cpuClear.radiance) peak = std::max({peak, p.r, p.g, p.b});
  const double psnrCovered = clouds::tools::psnr(gpu.radiance, cpuCovered.radiance, peak);
  const double psnrClear = clouds::tools::psnr(gpu.radiance, cpuClear.radiance, peak);
  std::printf(
      "bases see %.4f %.4f %.4f (clear sky's %.4f %.4f %.4f); against the CPU with them %.1f "
      "dB, with the clear sky's %.1f dB; opacity %.3f\n",
      covered.r, covered.g, covered.b, clear.r, clear.g, clear.b, psnrCovered, psnrClear,
      test::meanOpacity(gpu));
  ASSERT_GT(test::meanOpacity(gpu), 0.9) << "the view must be overcast";
  EXPECT_GE(psnrCovered, 40.0) << "the march's bases are lit by the last frame's sky light";
  EXPECT_LT(psnrClear, psnrCovered - 10.0) << "and not by the clear sky";
  // Greyer: the overcast's light on the ground is less blue than the clear sky's.
  EXPECT_LT(covered.b / covered.r, 0.7 * clear.b / clear.r);
}

// Under a clear sky the last frame's map is the host's sky, and clouds under it look as they did
// without the sky light: the bases' light differs only in how the host's sky is sampled (the map's
// texels, the sky ambient's 32 x 32 filtered samples).
TEST_F(SkyLight, UnderAClearSkyTheCloudsLookAsWithoutIt) {
  const HostSky host(device(), gradientSky());
  CloudView view = groundView(host.view());
  view.groundAlbedo = glm::vec3(0.3f, 0.25f, 0.2f);
  clouds::Settings clear = skyLit(clouds::tools::singleFrame(clouds::Settings{}));
  clear.coverage = 0.0f;
  std::vector<clouds::tools::CloudFrame> frames;
  for (const bool on : {true, false}) {
    clouds::Settings s = clear;
    s.skyLight = on;
    harness().cut();
    harness().render(view, s, kExtent);  // a clear sky: the map is the host's
    s.coverage = 0.55f;
    frames.push_back(harness().render(view, s, kExtent));
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < frames[0].radiance.size(); ++i) {
    const glm::dvec3 with(frames[0].radiance[i]);
    const glm::dvec3 without(frames[1].radiance[i]);
    worst = std::max(worst, std::abs(luminance(with) - luminance(without)) / luminance(without));
  }
  std::printf("clear sky: opacity %.3f, worst pixel %.5f of its luminance without the sky light\n",
              test::meanOpacity(frames[0]), worst);
  ASSERT_GT(test::meanOpacity(frames[0]), 0.1) << "the view must show clouds";
  EXPECT_LT(worst, 0.01);
}

TEST_F(SkyLight, HardCasesStayFinite) {
  const HostSky host(device(), gradientSky());
  struct Case {
    const char* name;
    double altitude;
    double sunElevation;
    double x;
  };
  const Case cases[] = {{"inside the layer", 2500.0, 30.0, 0.0},
                        {"above the layer", 9000.0, 30.0, 0.0},
                        {"sun below the horizon", 300.0, -8.0, 0.0},
                        {"far from the origin", 300.0, 30.0, 4.0e6}};
  for (const Case& c : cases) {
    CloudView view = groundView(host.view());
    view.position = {c.x, c.altitude, 0.0};
    view.sunElevationDegrees = c.sunElevation;
    harness().cut();
    harness().render(view, overcast(), kExtent);
    const SkyLightImage map = harness().readSkyLight();
    ASSERT_TRUE(map.measures.valid) << c.name;
    for (const glm::vec4& t : map.texels) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_TRUE(std::isfinite(t[k]) && t[k] >= 0.0f) << c.name;
      }
    }
    const glm::vec3 m = map.measures.upperIrradianceOverPi;
    EXPECT_TRUE(std::isfinite(m.r + m.g + m.b) && m.r >= 0.0f) << c.name;
  }
}

TEST_F(SkyLight, NeedsTheHostsSky) {
  CloudView view = test::cumulusView();
  const std::string error = harness().tryRender(view, overcast(), kExtent);
  EXPECT_NE(error.find("FrameInputs.skyView"), std::string::npos) << error;
}

// Off, the module makes no map, holds no memory for it and times no pass; on, it does.
TEST_F(SkyLight, OffItCostsNothing) {
  const HostSky host(device(), uniformSky());
  clouds::tools::HarnessOptions options;
  options.passTimings = true;
  for (const bool on : {false, true}) {
    clouds::tools::CloudHarness h(device(), kExtent, options);
    clouds::Settings s = overcast();
    s.skyLight = on;
    h.render(groundView(host.view()), s, kExtent);
    const std::vector<clouds::PassTiming> timings = h.lastPassTimings();
    const bool timed = std::any_of(timings.begin(), timings.end(), [](const auto& t) {
      return std::string(t.name) == "sky light";
    });
    EXPECT_EQ(timed, on);
    EXPECT_EQ(h.memoryUsage().skyLightBytes > 0, on);
    EXPECT_EQ(h.context().outputs().skyLight.image != VK_NULL_HANDLE, on);
    EXPECT_EQ(h.readSkyLight().measures.valid, on);
  }
}

}  // namespace
