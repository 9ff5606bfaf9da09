// The atmosphere's shared model (shaders/atmosphere_model.h compiled as C++ in double) against
// answers that do not come from the model itself: closed forms (transmittance through
// exponential layers and an ozone tent at the zenith, the phase functions' and the sun disc's
// normalisation), round trips of the LUT parameterisations, and physical facts each term is
// responsible for (Rayleigh makes the noon sky blue, Mie makes the aureole, the planet shadows,
// the ground bounces, multiple scattering adds what a brute-force second order predicts).
#include <gtest/gtest.h>

#include <cmath>

#include "atmosphere/atmosphere.h"
#include "atmosphere_model.h"
#include "atmosphere_reference.h"

namespace {

using atmosphere::Parameters;
using atmosphere::model::kPi;

constexpr double kThickness = 100e3;  // Earth's atmosphere, top - bottom (m)

// The optical depth of an exponential layer from altitude h straight up to the top.
double exponentialLayer(double coefficient, double scaleHeight, double h) {
  return coefficient * scaleHeight *
         (std::exp(-h / scaleHeight) - std::exp(-kThickness / scaleHeight));
}

// Zenith optical depth of Earth's parameters from altitude h, in closed form: two exponential
// layers and, from below the ozone layer, its whole tent (peak x half width).
glm::dvec3 zenithOpticalDepth(const Parameters& p, double h) {
  glm::dvec3 depth;
  for (int c = 0; c < 3; ++c) {
    depth[c] = exponentialLayer(p.rayleighScatteringPerMetre[c], p.rayleighScaleHeightMetres, h) +
               exponentialLayer(p.mieExtinctionPerMetre[c], p.mieScaleHeightMetres, h) +
               double(p.ozoneAbsorptionPerMetre[c]) * p.ozoneHalfWidthMetres;
  }
  return depth;
}

TEST(AtmosphereModel, ZenithTransmittanceMatchesTheClosedForm) {
  const Parameters earth;
  for (double altitude : {0.0, 1500.0, 8000.0}) {
    const glm::dvec3 expected = glm::exp(-zenithOpticalDepth(earth, altitude));
    const glm::vec3 got = atmosphere::sunTransmittance(earth, altitude, {0, 1, 0}, 4000);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(got[c], expected[c], 1e-3) << "altitude " << altitude << " channel " << c;
    }
  }
  // A single exponential Rayleigh layer (no Mie, no ozone): the textbook case.
  Parameters rayleighOnly;
  rayleighOnly.mieScatteringPerMetre = glm::vec3(0.0f);
  rayleighOnly.mieExtinctionPerMetre = glm::vec3(0.0f);
  rayleighOnly.ozoneAbsorptionPerMetre = glm::vec3(0.0f);
  const glm::vec3 got = atmosphere::sunTransmittance(rayleighOnly, 0.0, {0, 1, 0}, 4000);
  for (int c = 0; c < 3; ++c) {
    const double od = exponentialLayer(rayleighOnly.rayleighScatteringPerMetre[c], 8000.0, 0.0);
    EXPECT_NEAR(got[c], std::exp(-od), 1e-3) << "channel " << c;
  }
}

TEST(AtmosphereModel, SunTransmittanceReddensAsTheSunSetsAndIsZeroInThePlanetsShadow) {
  const Parameters earth;
  double previousRatio = 1e9;
  for (double elevation : {60.0, 30.0, 10.0, 3.0, 0.5}) {
    const double e = glm::radians(elevation);
    const glm::vec3 t = atmosphere::sunTransmittance(earth, 0.0, {std::cos(e), std::sin(e), 0.0});
    const double blueOverRed = t.b / t.r;
    EXPECT_LT(blueOverRed, previousRatio) << "elevation " << elevation;
    previousRatio = blueOverRed;
  }
  // Below the horizon the planet is in the way; higher up the sun is still seen.
  const glm::dvec3 below{std::cos(0.05), -std::sin(0.05), 0.0};
  EXPECT_EQ(atmosphere::sunTransmittance(earth, 0.0, below), glm::vec3(0.0f));
  EXPECT_GT(atmosphere::sunTransmittance(earth, 30000.0, below).r, 0.1f);
}

TEST(AtmosphereModel, PhaseFunctionsIntegrateToOneOverTheSphere) {
  const int steps = 20000;
  for (double g : {0.0, 0.8, -0.5}) {
    double rayleigh = 0.0;
    double mie = 0.0;
    for (int i = 0; i < steps; ++i) {
      // d(solid angle) = 2 pi d(cos theta); midpoint rule in cos theta.
      const double cosTheta = -1.0 + (i + 0.5) * 2.0 / steps;
      rayleigh += atmosphere::model::rayleighPhase(cosTheta) * 2.0 * kPi * 2.0 / steps;
      mie += atmosphere::model::miePhase(g, cosTheta) * 2.0 * kPi * 2.0 / steps;
    }
    EXPECT_NEAR(rayleigh, 1.0, 1e-6);
    EXPECT_NEAR(mie, 1.0, 2e-3) << "g " << g;
  }
  // Mie scatters forward, Rayleigh symmetrically.
  EXPECT_GT(atmosphere::model::miePhase(0.8, 1.0), 50.0 * atmosphere::model::miePhase(0.8, 0.0));
  EXPECT_DOUBLE_EQ(atmosphere::model::rayleighPhase(0.7), atmosphere::model::rayleighPhase(-0.7));
}

TEST(AtmosphereModel, SunDiscCarriesTheSunsIlluminanceAndDarkensTowardsItsLimb) {
  const double radius = Parameters{}.sunAngularRadiusRadians;
  const auto versine = [](double angle) { return 2.0 * std::pow(std::sin(0.5 * angle), 2.0); };
  const int steps = 20000;
  double illuminance = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double angle = (i + 0.5) * radius / steps;
    illuminance += atmosphere::model::sunDiscRadiance(versine(angle), versine(radius)) * 2.0 * kPi *
                   std::sin(angle) * radius / steps;
  }
  EXPECT_NEAR(illuminance, 1.0, 1e-3);
  const double centre = atmosphere::model::sunDiscRadiance(0.0, versine(radius));
  const double limb = atmosphere::model::sunDiscRadiance(versine(radius * 0.999), versine(radius));
  EXPECT_NEAR(limb / centre, 0.4 + 0.6 * std::sqrt(1.0 - 0.999 * 0.999), 1e-3);
  EXPECT_EQ(atmosphere::model::sunDiscRadiance(versine(radius * 1.01), versine(radius)), 0.0);
}

TEST(AtmosphereModel, TheMultipleScatteringLutCrowdsItsTexelsAtTheTerminator) {
  using namespace atmosphere::model;
  const atmosphere::reference::Reference reference(Parameters{}, atmosphere::Settings{});
  const AtmosphereModel& a = reference.model();
  // The sun-angle step between neighbouring texels of a 32-texel LUT, at the terminator and at
  // the zenith: twilight, where the upper air's light changes fastest, gets the finer one.
  const auto step = [&](double muSun) {
    double altitude = 0.0;
    double lo = 0.0;
    double hi = 0.0;
    const dvec2 uv = multiScatteringUv(a.bottomRadius, muSun, a, 32.0);
    multiScatteringParams(uv - dvec2(0.5 / 32.0, 0.0), 32.0, a, altitude, lo);
    multiScatteringParams(uv + dvec2(0.5 / 32.0, 0.0), 32.0, a, altitude, hi);
    return hi - lo;
  };
  EXPECT_LT(step(-0.07), 0.6 * (2.0 / 31.0)) << "finer than a linear axis at 4 degrees down";
  EXPECT_LT(step(-0.07), 0.5 * step(0.9));
}

TEST(AtmosphereModel, LutParameterisationsRoundTrip) {
  using namespace atmosphere::model;
  const atmosphere::reference::Reference reference(Parameters{}, atmosphere::Settings{});
  const AtmosphereModel& a = reference.model();
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const dvec2 uv((x + 0.5) / 16.0, (y + 0.5) / 16.0);
      double r = 0.0;
      double mu = 0.0;
      transmittanceParams(uv, a, r, mu);
      const dvec2 back = transmittanceUv(r, mu, a);
      EXPECT_NEAR(back.x, uv.x, 1e-6);
      EXPECT_NEAR(back.y, uv.y, 1e-6);
      EXPECT_FALSE(rayHitsGround(r, mu, a)) << "the LUT holds only rays that miss the ground";
      double msAltitude = 0.0;
      double muSun = 0.0;
      multiScatteringParams(uv, 16.0, a, msAltitude, muSun);
      const dvec2 msBack = multiScatteringUv(a.bottomRadius + msAltitude, muSun, a, 16.0);
      EXPECT_NEAR(msBack.x, uv.x, 1e-6);
      EXPECT_NEAR(msBack.y, uv.y, 1e-6);
      for (double altitude : {1.0, 300.0, 20000.0}) {
        const double cameraRadius = a.bottomRadius + altitude;
        const dvec2 size(192, 108);
        const dvec2 texel = (glm::floor(uv * size) + 0.5) / size;
        double viewZenithCos = 0.0;
        double lightViewCos = 0.0;
        const double beta = horizonDip(cameraRadius, a);
        skyViewParams(texel, beta, size, viewZenithCos, lightViewCos);
        const dvec2 again = skyViewUv(viewZenithCos, lightViewCos, beta, size);
        // The lower half of the LUT is exactly the directions that hit the ground.
        EXPECT_EQ(rayHitsGround(cameraRadius, viewZenithCos, a), texel.y > 0.5) << altitude;
        EXPECT_NEAR(again.x, texel.x, 1e-6) << altitude;
        EXPECT_NEAR(again.y, texel.y, 1e-6) << altitude;
      }
    }
  }
}

// The sky's radiance from the ground (unit sun) along world direction `view`.
glm::dvec3 skyRadiance(const atmosphere::reference::Reference& reference, glm::dvec3 view,
                       glm::dvec3 sun) {
  return reference.scattering(1.0, view, sun, 200).luminance;
}

glm::dvec3 direction(double azimuthDegrees, double elevationDegrees) {
  const double a = glm::radians(azimuthDegrees);
  const double e = glm::radians(elevationDegrees);
  return {std::sin(a) * std::cos(e), std::sin(e), -std::cos(a) * std::cos(e)};
}

TEST(AtmosphereReference, RayleighMakesTheNoonSkyBlue) {
  const atmosphere::reference::Reference earth(Parameters{}, atmosphere::Settings{});
  const glm::dvec3 zenith = skyRadiance(earth, {0, 1, 0}, direction(0, 60));
  EXPECT_GT(zenith.b, 1.5 * zenith.g);
  EXPECT_GT(zenith.g, zenith.r);
  Parameters noRayleigh;
  noRayleigh.rayleighScatteringPerMetre = glm::vec3(0.0f);
  const atmosphere::reference::Reference hazeOnly(noRayleigh, atmosphere::Settings{});
  const glm::dvec3 grey = skyRadiance(hazeOnly, {0, 1, 0}, direction(0, 60));
  EXPECT_LT(grey.b, 1.2 * grey.r) << "Mie alone is grey";
  EXPECT_LT(grey.b, 0.3 * zenith.b);
}

TEST(AtmosphereReference, MieMakesTheAureoleAroundTheSun) {
  // Five degrees from the sun against the same elevation across the sky: Rayleigh's phase
  // alone makes the first about twice the second; Mie's forward peak adds the aureole.
  const glm::dvec3 sun = direction(0, 30);
  const auto contrast = [&](const Parameters& p) {
    const atmosphere::reference::Reference reference(p, atmosphere::Settings{});
    return skyRadiance(reference, direction(0, 35), sun).g /
           skyRadiance(reference, direction(90, 35), sun).g;
  };
  Parameters noMie;
  noMie.mieScatteringPerMetre = glm::vec3(0.0f);
  noMie.mieExtinctionPerMetre = glm::vec3(0.0f);
  const double withMie = contrast(Parameters{});
  const double withoutMie = contrast(noMie);
  EXPECT_LT(withoutMie, 2.2);
  EXPECT_GT(withMie, 1.4 * withoutMie);
}

TEST(AtmosphereReference, OzoneKeepsTheTwilightZenithBlue) {
  // At sunset the zenith's light has crossed the ozone layer sideways: its Chappuis band
  // absorbs yellow-green to red, which keeps the twilight zenith blue (Hulburt 1953).
  const atmosphere::Settings settings;
  const atmosphere::reference::Reference earth(Parameters{}, settings);
  Parameters noOzone;
  noOzone.ozoneAbsorptionPerMetre = glm::vec3(0.0f);
  const atmosphere::reference::Reference withoutOzone(noOzone, settings);
  const glm::dvec3 sun = direction(0, 0.5);
  const glm::dvec3 with = skyRadiance(earth, {0, 1, 0}, sun);
  const glm::dvec3 without = skyRadiance(withoutOzone, {0, 1, 0}, sun);
  EXPECT_GT(with.b / with.g, 1.3 * (without.b / without.g));
  EXPECT_GT(with.b / with.r, 1.05 * (without.b / without.r));
}

TEST(AtmosphereReference, TheGroundBouncesLightIntoTheSkyAndItsOwnRadiance) {
  const atmosphere::Settings settings;
  Parameters dark;
  dark.groundAlbedo = glm::vec3(0.0f);
  Parameters snow;
  snow.groundAlbedo = glm::vec3(0.9f);
  const atmosphere::reference::Reference black(dark, settings);
  const atmosphere::reference::Reference white(snow, settings);
  const glm::dvec3 sun = direction(0, 40);
  // Looking down from 2 km: the ground itself, through the air.
  const glm::dvec3 down = direction(90, -30);
  const double groundBlack = black.scattering(2000.0, down, sun, 200, 1e12, true).luminance.g;
  const double groundWhite = white.scattering(2000.0, down, sun, 200, 1e12, true).luminance.g;
  EXPECT_GT(groundWhite, 4.0 * groundBlack);
  // The sky above gets brighter too: light bounced off the ground scatters back down (through
  // the multiple-scattering LUT).
  EXPECT_GT(skyRadiance(white, {0, 1, 0}, sun).g, 1.05 * skyRadiance(black, {0, 1, 0}, sun).g);
}

// Single scattering (real phase functions, the sunlit ground bouncing) arriving at `point`
// from every direction, scattered once more towards -`view`, integrated along the view ray: the
// second order of the sky's radiance by brute force, without the multiple-scattering LUT.
glm::dvec3 secondOrderByBruteForce(const atmosphere::reference::Reference& reference,
                                   glm::dvec3 view, glm::dvec3 sun) {
  using namespace atmosphere::model;
  const AtmosphereModel& a = reference.model();
  reference.bindToThisThread();
  const glm::dvec3 origin(0.0, a.bottomRadius + 1.0, 0.0);
  const double length = raySphere(glm::length(origin), view.y, a.topRadius);
  const int viewSamples = 24;
  const int grid = 24;
  glm::dvec3 total(0.0);
  glm::dvec3 transmittance(1.0);
  const double dt = length / viewSamples;
  for (int i = 0; i < viewSamples; ++i) {
    const glm::dvec3 point = origin + view * ((i + 0.5) * dt);
    const Medium m = sampleMedium(glm::length(point) - a.bottomRadius, a);
    // Rotate the sphere's grid into the frame where the point's up is +Y (atmosphere_model.h's
    // integrals assume the planet's centre straight below the origin).
    const glm::dvec3 up = glm::normalize(point);
    const glm::dvec3 side = glm::normalize(glm::cross(up, glm::dvec3(0, 0, 1)));
    const glm::dvec3 third = glm::cross(side, up);
    const auto toLocal = [&](glm::dvec3 w) {
      return glm::dvec3(glm::dot(w, side), glm::dot(w, up), glm::dot(w, third));
    };
    const glm::dvec3 localSun = toLocal(sun);
    const glm::dvec3 localView = toLocal(view);
    const glm::dvec3 localOrigin(0.0, glm::length(point), 0.0);
    glm::dvec3 inScattered(0.0);
    for (int p = 0; p < grid; ++p) {
      for (int q = 0; q < grid; ++q) {
        const double azimuth = 2.0 * kPi * (p + 0.5) / grid;
        const double cosPolar = 1.0 - 2.0 * (q + 0.5) / grid;
        const double sinPolar = std::sqrt(1.0 - cosPolar * cosPolar);
        const glm::dvec3 d(std::cos(azimuth) * sinPolar, cosPolar, std::sin(azimuth) * sinPolar);
        Scattering single = integrateScattering(localOrigin, d, localSun, 1e9, 48, kPhaseAtmosphere,
                                                0u, 32.0, 1u, a);
        const double cosTheta = glm::dot(d, localView);
        const glm::dvec3 phase =
            m.rayleigh * rayleighPhase(cosTheta) + m.mie * miePhase(a.miePhaseG, cosTheta);
        inScattered += single.luminance * phase * (4.0 * kPi / (grid * grid));
      }
    }
    const glm::dvec3 step = glm::exp(-m.extinction * dt);
    total += transmittance * inScattered * (glm::dvec3(1.0) - step) / m.extinction;
    transmittance *= step;
  }
  return total;
}

TEST(AtmosphereReference, MultipleScatteringAddsWhatTheSecondOrderPredicts) {
  const atmosphere::Settings settings;
  const atmosphere::reference::Reference earth(Parameters{}, settings);
  using namespace atmosphere::model;
  const AtmosphereModel& a = earth.model();
  for (double elevation : {60.0, 10.0}) {
    const glm::dvec3 sun = direction(0, elevation);
    const glm::dvec3 view = direction(120, 40);
    const glm::dvec3 origin(0.0, a.bottomRadius + 1.0, 0.0);
    const glm::dvec3 all = skyRadiance(earth, view, sun);
    earth.bindToThisThread();
    const glm::dvec3 singleOnly =
        integrateScattering(origin, view, sun, 1e9, 200, kPhaseAtmosphere, 0u, 32.0, 0u, a)
            .luminance;
    const glm::dvec3 fromTheLut = all - singleOnly;
    const glm::dvec3 secondOrder = secondOrderByBruteForce(earth, view, sun);
    const glm::dvec3 share = fromTheLut / secondOrder;
    for (int c = 0; c < 3; ++c) {
      // Every order past the first adds to the second, so the LUT's share is at least the
      // brute-force second order (the LUT's isotropic second order is 2 to 5% under it here,
      // which the higher orders more than make up); Earth's air re-scatters under half of
      // what it scatters (f_ms < 0.5), so all orders are under twice the second.
      EXPECT_GT(share[c], 1.0) << "elevation " << elevation << " channel " << c;
      EXPECT_LT(share[c], 2.0) << "elevation " << elevation << " channel " << c;
    }
    // The higher orders matter more where the air is thicker: blue's share exceeds red's
    // (the geometric series 1 / (1 - f_ms); without it the shares are within 6%).
    EXPECT_GT(share.b, 1.15 * share.r) << "elevation " << elevation;
  }
}

}  // namespace
