// The cloud ray-march, shared by the GPU march shader and the CPU reference renderer.
//
// The layer is a spherical shell around a planet whose centre is always straight below the
// camera: the world is a flat map (x, z) with y the altitude, and the sky curves away from the
// viewer, so a frame 100 km from the origin is computed exactly like one at the origin (the
// host-side offsets into the tiling textures are computed in double precision). The march:
//  - finds the segment of the view ray inside the shell (camera below, inside or above), stops
//    at the host's scene depth and at the maximum distance, and skips rays that hit the ground;
//  - steps with a length that grows with distance (Schneider 2022: near step + growth x t),
//    shorter still within a few steps of the camera (half the distance), stretched to the
//    sample budget where a long ray would not reach its end;
//  - takes coarse steps on cheap low-frequency samples in empty space and steps back into fine
//    steps with full detail on a hit, returning to coarse steps after a run of empty samples;
//  - marches towards the sun only where there is cloud (a cone of samples with growing spacing
//    and no detail; with light reuse on every other step while the ray stays in cloud),
//    integrates each step energy-conservingly, and exits early once the transmittance is
//    negligible (renormalising, so no energy is lost).
// lavapipe executes the body of an `if` whenever it is reached, even when no lane takes it, so
// data-dependent work sits in loops whose trip count is 0 when there is nothing to do
// (CLOUDS_WHEN below), and feature toggles arrive as compile-time constants (MarchOptions).
// kHeroCompiledOut: code only hero clouds need sits under a plain `if` on a specialization
// constant (heroCloudCount() > 0u, heroLightMode()), never in a CLOUDS_WHEN loop: the compiler
// removes an `if` whose condition is constant false, but keeps a loop of 0 trips that holds
// other loops, and that dead code slowed the march without hero clouds by 15%. (Where the
// variant has hero clouds, its frames have some: the `if` is always taken.)
#ifndef CLOUDS_CLOUD_MARCH_H
#define CLOUDS_CLOUD_MARCH_H

#include "cloud_density.h"
#include "cloud_hero.h"
#include "cloud_hero_light.h"
#include "cloud_lighting.h"
#include "cloud_math.h"
#include "cloud_noise.h"
#include "cloud_sampling.h"

FX_SHADER_BEGIN(clouds::shader)

const float kInfiniteDistance = 1e30f;
const int kMaxSkips = 96;       // empty weather cells a view ray may jump over
const int kMaxHeroSteps = 384;  // samples inside hero clouds' boxes, on top of the layer's
const int kFarShadowEvery = 4;  // steps between reads of the shadow map beyond the light cone

// The includer's: the share of the sun [0, 1] a sample at a camera-relative (x, z) and an
// altitude (m) gets past the host's terrain (1 where the includer knows no terrain).
float terrainSunLight(vec3 flatOffset, float altitude);
// The includer's: the clouds' optical depth towards the sun beyond a sample's light cone, from
// the cloud shadow map (0 where the includer has none).
float farCloudOpticalDepth(vec3 flatOffset, float altitude);
// The includer's: how hero clouds shadow themselves (kHeroLight*; heroSunward()), a
// specialization constant in the march (kHeroLightCone in variants without hero clouds: a
// condition on a MarchOptions member did not fold away there, and the dead code cost the
// variant's march 15% on lavapipe).
uint heroLightMode();

struct MarchOptions {
  uint detail;              // high-frequency erosion
  uint cheapSampling;       // coarse steps in empty space
  uint multipleScattering;  // octave approximation
  uint lightSteps;          // samples towards the sun per cloudy view sample
  uint emptySpace;          // jump over weather cells without cloud
  uint lightReuse;          // the sun's optical depth on every other step (lightOpticalDepth())
  // The near/far split (u.nearFieldMetres; 0 there: none): kMarchNearPart marches the ray up to
  // it (the near field's pass), kMarchFarPart from it on (the tiles' march, and the CPU
  // reference's whole rays), kMarchWholeRay all of it whatever the split (the sky light's).
  uint nearField;
};
const uint kMarchFarPart = 0u;
const uint kMarchNearPart = 1u;
const uint kMarchWholeRay = 2u;

struct MarchResult {
  vec3 radiance;        // in-scattered radiance towards the camera (premultiplied)
  float transmittance;  // of the whole ray through the layer
  float frontDepth;     // distance (m) to the first cloudy sample; 0 when none
  float weightedDepth;  // transmittance-weighted mean distance (m) of the cloud; 0 when none
  float viewSamples;    // density samples taken along the view ray
  float lightSamples;   // density samples taken towards the sun
  float skippedCells;   // empty weather cells jumped over
  uint earlyExit;       // 1 when the transmittance cutoff ended the ray
};

// Altitude after travelling `t` along a ray from `altitude` whose cosine with the local up is
// `cosZenith`. Written as altitude + delta / (sqrt(r0^2 + delta) + r0) to avoid subtracting
// two planet radii in float.
FX_INLINE float altitudeAlongRay(float t, float cosZenith, float altitude, float radius) {
  const float r0 = radius + altitude;
  const float delta = t * (t + 2.0f * r0 * cosZenith);
  return altitude + delta / (sqrt(max(r0 * r0 + delta, 0.0f)) + r0);
}

// The [start, end) distances of a view ray inside the cloud shell; end <= start when the ray
// misses it or hits the ground first.
FX_INLINE vec2 layerSegment(float altitude, float cosZenith, IN(CloudUniforms) u) {
  const float radius = u.planetRadiusMetres;
  const float bottom = u.layerBottomMetres;
  const float top = u.layerTopMetres;
  const vec2 ground = raySphere(max(altitude, 0.0f), cosZenith, 0.0f, radius);
  const float tGround = ground.x > 0.0f ? ground.x : kInfiniteDistance;
  const vec2 inner = raySphere(altitude, cosZenith, bottom, radius);
  const vec2 outer = raySphere(altitude, cosZenith, top, radius);
  float start = 0.0f;
  float end = 0.0f;
  if (altitude < bottom) {
    start = inner.y;  // leaving the inner sphere from inside
    end = outer.y;
  } else if (altitude <= top) {
    start = 0.0f;
    end = outer.y;
    if (inner.x > 0.0f) end = min(end, inner.x);  // looking down through the base
  } else {
    start = max(outer.x, 0.0f);
    end = inner.x > 0.0f ? inner.x : outer.y;
    if (outer.y < 0.0f) end = start;  // the shell is not hit at all
  }
  end = min(end, tGround);
  return vec2(start, end);
}

FX_INLINE float viewStepLength(float t, IN(CloudUniforms) u) {
  return u.viewStepMetres + u.viewStepGrowth * t;
}

// Near the camera a step is kNearStepRatio of its distance from it, never below a sixteenth of
// viewStepMetres, until that ratio reaches viewStepMetres (twice viewStepMetres from the
// camera: 120 m at Medium). These near steps (9 from the camera, whatever the settings) are
// taken on top of the sample budget. They matter only with the camera in or at the edge of
// cloud, where the cloud within a few hundred metres covers much of the screen and the rays of
// a whole region sample it at the same places: at the preset's step (60 m at Medium, or a long
// ray's budget-stretched step) a ray's haze hinged on where its one sample there fell. Flying
// inside a tall layer over the ground (Medium, 256x144) every ray started at 0.05 of its steps
// saw the ground through thin cloud 4x as bright as every ray started at 0.95 (1.2x with near
// steps), and a frame's pattern of start offsets showed as a grid of dots. Taken out of the
// budget instead, they cost the far steps of long rays: High lost 1.2 dB on the static
// "inside the layer" view towards its horizon.
const float kNearStepRatio = 0.5f;
const float kNearStepMinFraction = 0.0625f;  // of viewStepMetres: the first steps' length
// Loop iterations the near steps may take: 9, each at most twice (a coarse sample that finds
// cloud is taken again as a fine one at the same place).
const int kMaxNearSteps = 18;
FX_INLINE bool isNearStep(float t, IN(CloudUniforms) u) {
  return kNearStepRatio * t < u.viewStepMetres;
}

// The step that starts `t` metres along a ray whose segment ends at `end`, with `samplesLeft`
// of its sample budget left; `scale` is 1 for fine steps, coarseStepFactor for coarse ones.
// Where the steps would run out before the segment's end (a long ray through a tall layer
// towards the horizon or the ground), they stretch to reach it rather than leave the far
// clouds unmarched; near the camera they are short (isNearStep).
FX_INLINE float marchStepLength(float t, float end, int samplesLeft, float scale,
                                IN(CloudUniforms) u) {
  if (isNearStep(t, u)) {
    return min(max(kNearStepRatio * t, u.viewStepMetres * kNearStepMinFraction), end - t);
  }
  const float budgetStep = (end - t) / float(max(samplesLeft, 1));
  return min(max(viewStepLength(t, u) * scale, budgetStep), end - t);
}

// One cloud-field evaluation at a point given camera-relative (flat) offset and altitude.
struct FieldSample {
  float heightFraction;
  float base;     // low-frequency density in [0, 1]
  float profile;  // low-frequency profile in [0, 1]: 0 at a cloud's edge, 1 in its core
  float density;  // final density in [0, 1] (base, eroded by detail when enabled)
  float sigmaT;   // extinction (1/m)
};

// How far downwind the shape at `heightFraction` leans from its base (x, z metres): skewMetres
// times the integral, from the base up, of the wind's direction, which turns by
// windShearRadians from the base to the top. So the lean's slope at each height is the wind's
// direction there, and a top leans the way the upper wind blows (Schneider 2017: anvils skewed
// by their own wind). R(a), counter-clockwise seen from above, takes d to
// cos(a) d + sin(a) (d_z, -d_x); over heights [0, h] that integrates to along d + across (d_z,
// -d_x).
FX_INLINE vec2 skewLean(float heightFraction, IN(CloudUniforms) u) {
  const float h = saturate(heightFraction);
  const float shear = u.windShearRadians;
  float along = h;                      // no shear: a straight lean
  float across = 0.5f * shear * h * h;  // a slight one: the series (no 0 / 0)
  if (abs(shear) > 1e-3f) {
    along = sin(shear * h) / shear;
    across = (1.0f - cos(shear * h)) / shear;
  }
  const vec2 d = u.windDirection;
  return u.skewMetres * (along * d + across * vec2(d.y, -d.x));
}

FX_INLINE vec3 noisePosition(vec3 flatOffset, float altitude, float heightFraction,
                             IN(CloudUniforms) u) {
  // Skew the shape downwind with height (Nubis: clouds lean with the wind as they rise): the
  // noise a base shows at p, a top shows downwind of it, so the top reads it from upwind.
  const vec2 skew = skewLean(heightFraction, u);
  return vec3(flatOffset.x - skew.x, altitude, flatOffset.z - skew.y);
}

// The detail noise at the noise position `p` (noisePosition()), its curl displacement
// (strongest at the base) applied.
FX_INLINE float layerDetailNoise(vec3 p, float heightFraction, int level, IN(CloudUniforms) u) {
  const vec2 curlUv = (u.curlOffsetMetres + vec2(p.x, p.z)) / u.curlTileMetres;
  const vec2 curl = sampleCurl(curlUv) * (u.curlStrengthMetres * (1.0f - heightFraction));
  const vec3 uvw = (u.detailOffsetMetres + p + vec3(curl.x, 0.0f, curl.y)) / u.detailTileMetres;
  return sampleDetailNoise(uvw, level);
}

// The layer's still field (the vertical-profile model, cloud_density.h): the weather over the
// column `column` (camera-relative x, z), the noise read at `p` (noisePosition()). `distance`
// (m) from the camera sets the noise's level of detail (noiseLevel(): the pixel's footprint
// there, u.noiseFootprintPerMetre x distance), `lodDither` in [0, 1) rounds it.
FX_INLINE FieldSample stillLayerField(vec2 column, vec3 p, float heightFraction, float distance,
                                      float lodDither, uint wantDetail, IN(CloudUniforms) u) {
  FieldSample s;
  s.heightFraction = heightFraction;
  // Coverage is held still (the weather map is not scrolled); the noise moves with the wind.
  const vec2 weatherUv = (u.weatherOffsetMetres + column) / u.weatherTileMetres;
  const WeatherSample w = decodeWeather(sampleWeather(weatherUv), columnWeather(column, u), u);
  const float footprint = distance * u.noiseFootprintPerMetre;
  const int shapeLevel = noiseLevel(footprint, u.shapeTileMetres / float(kShapeNoiseSize),
                                    lodDither, kShapeNoiseLevels);
  const float shapeNoise =
      sampleShapeNoise((u.shapeOffsetMetres + p) / u.shapeTileMetres, shapeLevel);
  const CoarseShape shape = coarseShape(shapeNoise, heightFraction, w);
  s.base = shape.density;
  s.profile = shape.profile;
  s.density = s.base;
  // Detail only where there is a base shape and the sample is near enough to show it.
  CLOUDS_WHEN(wantDetail != 0u && s.base > 0.0f && distance < u.detailDistanceMetres) {
    const int detailLevel = noiseLevel(footprint, u.detailTileMetres / float(kDetailNoiseSize),
                                       lodDither, kDetailNoiseLevels);
    s.density = erodeDensity(s.base, layerDetailNoise(p, heightFraction, detailLevel, u),
                             heightFraction, u.detailErosion);
  }
  s.sigmaT = s.density * w.density * u.extinctionPerMetre;
  return s;
}

FX_INLINE FieldSample mixFields(IN(FieldSample) a, IN(FieldSample) b, float t) {
  FieldSample s;
  s.heightFraction = a.heightFraction;
  s.base = mix(a.base, b.base, t);
  s.profile = mix(a.profile, b.profile, t);
  s.density = mix(a.density, b.density, t);
  s.sigmaT = mix(a.sigmaT, b.sigmaT, t);
  return s;
}

// The layer's field at a camera-relative (x, z) and an altitude on the curved shell: the still
// field, which a superstorm turns (cloud_vortex.h): there it is read where the point was before
// the storm turned it, once per flow phase, weather and noise alike, so that all of the storm's
// cloud (its bands included) moves with its turn and the history can follow it.
FX_INLINE FieldSample layerField(vec3 flatOffset, float altitude, float distance, float lodDither,
                                 uint wantDetail, IN(CloudUniforms) u) {
  FieldSample s;
  const float bottom = u.layerBottomMetres;
  const float top = u.layerTopMetres;
  s.heightFraction = (altitude - bottom) / max(top - bottom, 1.0f);
  s.base = 0.0f;
  s.profile = 0.0f;
  s.density = 0.0f;
  s.sigmaT = 0.0f;
  if (s.heightFraction < 0.0f || s.heightFraction > 1.0f) return s;
  if ((u.flags & kFlagHomogeneous) != 0u) {
    // Test mode: a homogeneous slab with extinction u.extinctionPerMetre, for analytic comparisons.
    s.base = 1.0f;
    s.profile = 1.0f;
    s.density = 1.0f;
    s.sigmaT = u.extinctionPerMetre;
    return s;
  }
  vec2 column = vec2(flatOffset.x, flatOffset.z);
  vec3 p = noisePosition(flatOffset, altitude, s.heightFraction, u);
  vec2 columnB = column;
  vec3 pB = p;
  float weightA = 1.0f;
  if (hasVortex(u)) {
    const WeatherRegionUniform storm = weatherRegion(u, u.vortexRegion);
    const vec2 eye = vec2(storm.placement.x, storm.placement.y);
    const float rate = vortexTurnRate(length(column - eye), storm);
    const vec2 columnA = eye + turnedCounterClockwise(column - eye, -rate * u.vortexClock.x);
    const vec2 pA = eye + turnedCounterClockwise(vec2(p.x, p.z) - eye, -rate * u.vortexClock.x);
    columnB = eye + turnedCounterClockwise(column - eye, -rate * u.vortexClock.y);
    const vec2 b = eye + turnedCounterClockwise(vec2(p.x, p.z) - eye, -rate * u.vortexClock.y);
    pB = vec3(b.x, p.y, b.y);
    column = columnA;
    p = vec3(pA.x, p.y, pA.y);
    weightA = rate != 0.0f ? u.vortexClock.z : 1.0f;
  }
  s = stillLayerField(column, p, s.heightFraction, distance, lodDither, wantDetail, u);
  CLOUDS_WHEN(weightA < 1.0f) {
    s = mixFields(
        stillLayerField(columnB, pB, s.heightFraction, distance, lodDither, wantDetail, u), s,
        weightA);
  }
  return s;
}

// The density seam: every density source of the module at one point, as the march, its light
// samples and the shadow map see it. `relative` is the camera-relative point on its straight
// line from the camera (the layer reads its x and z), `altitude` its altitude on the layer's
// curved shell. Sources: the layer (layerField()) and the hero clouds (cloud_hero.h); their
// extinctions add, and the lighting reads the profile and height of the denser. A new model
// adds its own term here (and its bounds to the march's span: marchClouds()). `heroExcluded`:
// hero clouds left out (bit i: instance i; a light sample's own, heroSunward()).
FX_INLINE FieldSample sampleField(vec3 relative, float altitude, float distance, float lodDither,
                                  uint wantDetail, uint heroExcluded, IN(CloudUniforms) u) {
  FieldSample s = layerField(relative, altitude, distance, lodDither, wantDetail, u);
  if (heroCloudCount() > 0u) {  // a plain if: kHeroCompiledOut
    HeroSample hero = heroFieldExcept(relative, u, heroExcluded);
    // Their detail where the layer's would be (wantDetail); light samples and coarse samples,
    // which only ask whether cloud can lie here (base), see them coarse.
    if (wantDetail != 0u) heroAddDetail(hero, distance * u.noiseFootprintPerMetre, lodDither);
    if (hero.sigmaT > s.sigmaT) {
      s.profile = hero.profile;
      s.heightFraction = hero.heightFraction;
    }
    s.base = max(s.base, hero.reach);
    s.density = max(s.density, hero.sigmaT > 0.0f ? hero.profile : 0.0f);
    s.sigmaT += hero.sigmaT;
  }
  return s;
}

// Distance along the flat (x, z) direction `d` from `p` to the boundary of its `cell`-metre
// grid cell, a little beyond so the next query lands in the next cell; 1e30 when d is vertical.
FX_INLINE float cellExitDistance(vec2 p, vec2 d, float cell) {
  const vec2 base = floor(p / cell) * cell;
  float exitX = kInfiniteDistance;
  float exitZ = kInfiniteDistance;
  if (d.x > 1e-7f) exitX = (base.x + cell - p.x) / d.x;
  if (d.x < -1e-7f) exitX = (base.x - p.x) / d.x;
  if (d.y > 1e-7f) exitZ = (base.y + cell - p.y) / d.y;
  if (d.y < -1e-7f) exitZ = (base.y - p.y) / d.y;
  return min(exitX, exitZ) + 0.01f;
}

// True when a weather cell's maxima (R coverage, G type) leave no cloud at `altitude` under the
// largest coverage and type its columns can have (columnWeatherCeiling()): zero coverage, or
// (for a ray whose altitude only grows) above the tallest cloud type's top.
FX_INLINE bool weatherCellEmpty(vec4 maxima, vec2 ceiling, float altitude, bool ascending,
                                IN(CloudUniforms) u) {
  const float coverage = layerCoverage(maxima.x, ceiling.x);
  const float type = saturate(ceiling.y + (maxima.y - 0.5f) * u.typeVariation);
  const float top =
      u.layerBottomMetres + typeProfile(type).w * (u.layerTopMetres - u.layerBottomMetres);
  return coverage <= 0.0f || (ascending && altitude > top);
}

// The ceiling of the weather over a `cell`-metre cell of the weather map's grid holding the
// point `p` (metres in the map's tile space).
FX_INLINE vec2 cellWeatherCeiling(vec2 p, float cell, IN(CloudUniforms) u) {
  const vec2 centre = (floor(p / cell) + 0.5f) * cell;
  return columnWeatherCeiling(centre - u.weatherOffsetMetres, cell * 0.70710678f, u);
}

FX_INLINE float emptySpaceSkip(vec2 origin, float t, vec3 rayDirection, float altitude,
                               IN(CloudUniforms) u) {
  const vec2 d = vec2(rayDirection.x, rayDirection.z);
  // A superstorm reads its weather where its turn brought it from (layerField()), which no
  // cell's maxima bound: no cell it reaches is skipped.
  if (hasVortex(u)) {
    const WeatherRegionUniform storm = weatherRegion(u, u.vortexRegion);
    const vec2 eye = vec2(storm.placement.x, storm.placement.y);
    const float reach = storm.shape.z + storm.shape.w + u.coarseCellMetres;
    if (length(origin + d * t - eye) < reach) return t;
  }
  const vec2 p = u.weatherOffsetMetres + origin + d * t;
  const bool ascending = rayDirection.y >= 0.0f;
  const float coarse = u.coarseCellMetres;
  const ivec2 coarseCell = ivec2(floor(p / coarse)) & (kWeatherMaxCoarseSize - 1);
  if (weatherCellEmpty(fetchWeatherMaxCoarse(coarseCell), cellWeatherCeiling(p, coarse, u),
                       altitude, ascending, u)) {
    return t + cellExitDistance(p, d, coarse);
  }
  const float fine = u.fineCellMetres;
  const ivec2 fineCell = ivec2(floor(p / fine)) & (kWeatherMaxFineSize - 1);
  if (weatherCellEmpty(fetchWeatherMaxFine(fineCell), cellWeatherCeiling(p, fine, u), altitude,
                       ascending, u)) {
    return t + cellExitDistance(p, d, fine);
  }
  return t;
}

// The cone kernel: the sideways direction of a ray's `index`-th light sample, a unit vector of
// a low-discrepancy sequence on the sphere (Roberts' R2 over height and azimuth) moved per ray by
// `rotation` in [0, 1)^2 (a Cranley-Patterson rotation). However many samples a ray takes,
// their directions spread over the sphere, and other rays (pixels, frames) take others, so the
// cone's spread is sampled uniformly on average. (A fixed hashed vector per index made each
// light-step count its own cone: the estimates of 10 and 16 steps differed, and neither
// converged on the Reference's 24.)
FX_INLINE vec3 coneKernel(uint index, vec2 rotation) {
  const float z = 1.0f - 2.0f * fract(rotation.x + float(index) * 0.7548776662f);
  const float azimuth = 2.0f * kPi * fract(rotation.y + float(index) * 0.5698402910f);
  const float radius = sqrt(max(1.0f - z * z, 0.0f));
  return vec3(radius * cos(azimuth), radius * sin(azimuth), z);
}

// The random numbers of the light samples of the rays of one round of refreshes (a pixel is
// refreshed once per round): x places each sample in its stretch of the cone, yz rotate the cone
// kernel (coneKernel()). All the rays of a round share them, so a frame shows no grain of
// per-pixel cones, and the rounds a pixel averages (as it averages its rays' start offsets)
// average the cone. Jitter mode 0 (none): the middle of each stretch and one cone for every
// ray, as deterministic as the view steps.
FX_INLINE vec3 lightJitter(uint round, uint mode) {
  if (mode == 0u) return vec3(0.5f);
  return hashCell(ivec3(int(round & 0xffffffu), 0, 0), 7127u);
}

// Optical depth towards the sun from a cloudy sample: the extinction integrated along the sun's
// direction over the cone length, each point spread sideways by d x lightConeSpread in a
// direction uniform over the sphere (the cone). Estimated by `steps` samples, one in each of
// `steps` stretches whose length grows quadratically with the distance (near the sample, where
// the shadowing detail is, they are short), at the place `jitter.x` in its stretch and in the
// direction coneKernel() gives it: a stratified estimate of one integral, so more steps are
// the same integral with less noise, and a ray's samples averaged over frames converge on it.
// Hero clouds in `heroExcluded` (bit i: instance i) are left out: the sample has their optical
// depth from heroSunward().
FX_INLINE float lightOpticalDepth(vec3 flatOffset, float altitude, float distance, float lodDither,
                                  uint steps, vec3 jitter, uint heroExcluded, IN(CloudUniforms) u,
                                  INOUT(float) samples) {
  const vec3 sun = u.sunDirection;
  const float coneLength = u.lightConeMetres;
  const float spread = u.lightConeSpread;
  float tau = 0.0f;
  for (uint j = 0u; j < steps; ++j) {
    const float s0 = float(j) / float(steps);
    const float s1 = float(j + 1u) / float(steps);
    const float d0 = coneLength * s0 * s0;
    const float d1 = coneLength * s1 * s1;
    const float d = mix(d0, d1, jitter.x);
    const vec3 offset = sun * d + coneKernel(j, vec2(jitter.y, jitter.z)) * (d * spread);
    // Over a few kilometres the curvature drop (d^2 / 2R, ~0.2 m) is negligible.
    const FieldSample s = sampleField(flatOffset + offset, altitude + offset.y, distance + d,
                                      lodDither, 0u, heroExcluded, u);
    tau += s.sigmaT * (d1 - d0);
    samples += 1.0f;
  }
  return tau;
}

// Whether the light cone (lightOpticalDepth()) from a sample at `altitude` can meet the layer:
// the layer can hold cloud (coverage and extinction), and the cone's altitudes, from
// min(0, sun.y - spread) to max(0, sun.y + spread) times its length about the sample's, reach
// its band.
FX_INLINE bool layerInLightCone(float altitude, IN(CloudUniforms) u) {
  const float reach = u.lightConeMetres;
  const float lowest = altitude + reach * min(u.sunDirection.y - u.lightConeSpread, 0.0f);
  const float highest = altitude + reach * max(u.sunDirection.y + u.lightConeSpread, 0.0f);
  const bool holdsCloud =
      (u.flags & kFlagHomogeneous) != 0u ||
      (layerCoverage(1.0f, u.fullestCoverage) > 0.0f && u.extinctionPerMetre > 0.0f);
  return holdsCloud && highest >= u.layerBottomMetres && lowest <= u.layerTopMetres;
}

// View-space unit direction of the ray through a pixel centre (pixel units, y down).
FX_INLINE vec3 viewRayDirection(vec2 pixelCentre, vec2 extent, IN(CloudUniforms) u) {
  const vec2 ndc = pixelCentre / extent * 2.0f - 1.0f;
  // A point on the near plane: depth 1 with reversed-Z, 0 otherwise; finite either way.
  const float nearDepth = (u.flags & kFlagReversedZ) != 0u ? 1.0f : 0.0f;
  const vec4 view = u.inverseProjection * vec4(ndc.x, ndc.y, nearDepth, 1.0f);
  const vec3 direction = vec3(view) / view.w;
  return direction / max(length(direction), 1e-20f);
}

// World-space unit direction of the view ray through a pixel centre (pixel units, y down).
FX_INLINE vec3 pixelRayDirection(vec2 pixelCentre, vec2 extent, IN(CloudUniforms) u) {
  return vec3(u.viewToWorld * vec4(viewRayDirection(pixelCentre, extent, u), 0.0f));
}

// Distance along the pixel's ray to the host geometry for a depth-buffer value; the sky
// (far plane, or depth 0 with reversed-Z) is kInfiniteDistance.
FX_INLINE float sceneDistanceFromDepth(float depth, vec2 pixelCentre, vec2 extent,
                                       IN(CloudUniforms) u) {
  const bool reversed = (u.flags & kFlagReversedZ) != 0u;
  if ((u.flags & kFlagHasDepth) == 0u) return kInfiniteDistance;
  if (reversed ? depth <= 0.0f : depth >= 1.0f) return kInfiniteDistance;
  const vec2 ndc = pixelCentre / extent * 2.0f - 1.0f;
  const vec4 view = u.inverseProjection * vec4(ndc.x, ndc.y, depth, 1.0f);
  if (abs(view.w) < 1e-30f) return kInfiniteDistance;
  return length(vec3(view) / view.w);
}

// Ray-start jitter in [0, 1) for a pixel: a 4x4 Bayer pattern over the pixels (the pixels of a
// tile, marched in turn, start apart; the rays of one frame, at the same place in each tile,
// start together: a frame without history interpolates them without a pattern), moved by
// this round's `startOffset` (refreshStartOffset()), which moves along each pixel's own
// refreshes. (Over the frame index, a pixel refreshed every 16th frame saw Halton points 16
// apart, whose lowest four bits are the same: offsets within 1/16 of each other, a fixed
// pattern of dots no accumulation removes.) `spreadOverTiles` (a frame without history inside
// the layer, where thin cloud all around makes a ray's result depend much on where it starts,
// so that rays starting together bias the whole frame) also spreads a frame's rays over a 2x2
// Bayer pattern of the tiles of side `tileSize`, which reconstruct.comp's tent averages
// exactly (it weighs even and odd tiles alike).
FX_INLINE float rayJitter(uvec2 pixel, float startOffset, uint tileSize, bool spreadOverTiles,
                          uint mode) {
  if (mode == 0u) return 0.5f;
  const uint k = max(tileSize, 1u);
  const float tiles = spreadOverTiles ? bayer2x2(pixel / k) : 0.0f;
  return fract(bayer4x4(pixel) + startOffset + tiles);
}

// The sky light's rays (Settings::skyLight): the world direction (unit) through the centre of
// texel `texel` of its equirectangular map (kSkyLightWidth x kSkyLightHeight; u = azimuth
// from +x towards +z, v = 0 at the zenith, 0.5 at the horizon).
FX_INLINE vec3 skyLightDirection(uvec2 texel) {
  const vec2 uv = (vec2(texel) + 0.5f) / vec2(float(kSkyLightWidth), float(kSkyLightHeight));
  const float azimuth = 2.0f * kPi * uv.x;
  const float elevation = kPi * (0.5f - uv.y);
  return vec3(cos(azimuth) * cos(elevation), sin(elevation), sin(azimuth) * cos(elevation));
}

// Where a sky-light ray starts in its first step, in [0, 1): a hash of its texel, moved by the
// golden ratio from one frame to the next, so that each refresh of a texel starts elsewhere and
// neighbouring texels never together (`mode`: the jitter, 0 none).
FX_INLINE float skyLightJitter(uvec2 texel, uint temporalIndex, uint mode) {
  if (mode == 0u) return 0.5f;
  const float hash = hashCell(ivec3(int(texel.x), int(texel.y), 0), 7919u).x;
  return fract(hash + 0.6180340f * float(temporalIndex & 0xffffu));
}

// The optical depth towards the sun of a cloudy sample on a ray through hero clouds lit by
// their light volume (heroLightMode() kHeroLightVolume or kHeroLightMarched): the clouds whose
// boxes hold the sample give their own (heroSunward()); the cone takes what else lies sunwards,
// when anything else can (Nubis³'s saving: a sample in a lone hero cloud above the layer marches no
// light). A sample in no box takes `farOpticalDepth` beyond the cone too, as on any other ray (in
// a box, the map would count that hero cloud a second time).
FX_INLINE float heroLitSun(vec3 flatOffset, float altitude, float distance, float lodDither,
                           vec3 lightRandom, float farOpticalDepth, IN(CloudUniforms) u,
                           IN(MarchOptions) o, INOUT(float) samples) {
  const HeroSunward hero = heroSunward(flatOffset, u, heroLightMode());
  const bool coneNeeded = hero.covered == 0u || heroCloudCount() > uint(bitCount(hero.covered)) ||
                          layerInLightCone(altitude, u);
  float tau = hero.opticalDepth + (hero.covered == 0u ? farOpticalDepth : 0.0f);
  // A loop of 0 or 1 trips around the cone, whose own trip count stays the constant
  // o.lightSteps (a count chosen per sample would keep the compiler from unrolling it).
  for (int cone = 0; cone < (coneNeeded ? 1 : 0); ++cone) {
    tau += lightOpticalDepth(flatOffset, altitude, distance, lodDither, o.lightSteps, lightRandom,
                             hero.covered, u, samples);
  }
  return tau;
}

// Marches one view ray. `rayDirection` is a unit world-space vector (y up), `sceneDistance`
// the distance to the host's geometry along it (kInfiniteDistance for sky), `jitter` in [0, 1)
// places each step's sample in its step and rounds the noise's level of detail, `lightRandom`
// places the light samples (lightJitter()).
FX_INLINE MarchResult marchClouds(vec3 rayDirection, float sceneDistance, float jitter,
                                  vec3 lightRandom, IN(CloudUniforms) u, IN(MarchOptions) o) {
  MarchResult r;
  r.radiance = vec3(0.0f);
  r.transmittance = 1.0f;
  r.frontDepth = 0.0f;
  r.weightedDepth = 0.0f;
  r.viewSamples = 0.0f;
  r.lightSamples = 0.0f;
  r.skippedCells = 0.0f;
  r.earlyExit = 0u;

  const float altitude = u.cameraAltitudeMetres;
  const float cosZenith = rayDirection.y;
  const vec2 segment = layerSegment(altitude, cosZenith, u);
  // Hero clouds extend the march to their boxes, beyond the layer where they stand out of it.
  vec3 heroSpan = vec3(kHeroFar, -kHeroFar, kHeroFar);
  if (heroCloudCount() > 0u) {  // kHeroCompiledOut
    heroSpan = heroRaySpan(vec3(0.0f), rayDirection, 0.0f);
  }
  const bool layerHit = segment.y > segment.x;
  const bool heroHit = heroSpan.y > heroSpan.x;
  // The part of the ray this march takes (MarchOptions::nearField): the two parts meet at
  // u.nearFieldMetres, and laid one over the other they are the whole ray.
  const float from = o.nearField == kMarchFarPart ? u.nearFieldMetres : 0.0f;
  const float to = min(u.maxDistanceMetres,
                       o.nearField == kMarchNearPart ? u.nearFieldMetres : kInfiniteDistance);
  const float start =
      max(heroHit ? (layerHit ? min(segment.x, heroSpan.x) : heroSpan.x) : segment.x, from);
  const float layerEnd = min(min(segment.y, sceneDistance), to);
  const float end =
      heroHit ? min(min(layerHit ? max(segment.y, heroSpan.y) : heroSpan.y, sceneDistance), to)
              : layerEnd;
  const OctavePhases phases = octavePhases(dot(rayDirection, u.sunDirection), u);
  const float albedo = u.albedo;
  const float cutoff = u.transmittanceCutoff;
  const float coarseFactor = max(u.coarseStepFactor, 1.0f);
  const int zeroRunToCoarse = int(u.emptySamplesToCoarse);
  const int maxSteps = int(u.maxViewSteps);

  float weightedDepthSum = 0.0f;
  float t = start;  // boundary of the current step; the sample sits at t + jitter * step
  // A ray that starts in a hero cloud's box starts with fine steps: its first coarse sample
  // would most likely find cloud and be taken again. So does the far part of a split ray: one
  // coarse step (3.3 fine ones at High) from the split would skip thin cloud that the whole
  // ray, short-stepped near the camera, reached the split finding (flying through sparse layer
  // at High, 160x90: 33.2 dB starting coarse, 33.9 fine, as one march).
  bool fine = o.cheapSampling == 0u || (heroHit && heroSpan.x <= start) || from > 0.0f;
  int emptyRun = 0;
  int samples = 0;
  int heroSamples = 0;  // samples inside hero clouds' boxes: a budget of their own
  // The optical depth towards the sun of the last cloudy sample, while the ray is in cloud.
  float sunOpticalDepth = 0.0f;
  bool inCloud = false;
  // The shadow map's optical depth beyond the light cone (farCloudOpticalDepth()), read where
  // the ray enters cloud and then every kFarShadowEvery-th step: the map holds the
  // low-frequency shape at tens to hundreds of metres a texel (what reading it less often saves
  // on lavapipe: docs/measurements.md, "The clouds' shadow on themselves").
  float farOpticalDepth = 0.0f;
  // Jumps over empty cells do not spend the sample budget (a long ray over clear sky must
  // still reach the clouds behind it); kMaxSkips bounds them. Nor do the near steps.
  const int iterations = maxSteps + kMaxSkips + kMaxNearSteps + (heroHit ? kMaxHeroSteps : 0);
  for (int i = 0; i < iterations; ++i) {
    if (t >= end || r.transmittance < cutoff || samples >= maxSteps) break;
    // Without hero clouds every step lies in the layer's segment.
    const bool inLayer = !heroHit || (layerHit && t >= segment.x && t < segment.y);
    const bool inHero = heroHit && t >= heroSpan.x && t < heroSpan.y;
    if (!inLayer && !inHero) {
      // Between the layer and the hero clouds' boxes there is nothing to sample.
      t = min(layerHit && t < segment.x ? segment.x : kInfiniteDistance,
              t < heroSpan.x ? heroSpan.x : kInfiniteDistance);
      continue;
    }
    // In a hero cloud's box with the last sample in cloud no jump is possible (its signed
    // distance bounds every jump there): the lookups are skipped.
    if (o.emptySpace != 0u && !(inHero && inCloud)) {
      float skipTo =
          inLayer
              ? emptySpaceSkip(vec2(0.0f), t, rayDirection,
                               altitudeAlongRay(t, cosZenith, altitude, u.planetRadiusMetres), u)
              : (layerHit && t < segment.x ? segment.x : kInfiniteDistance);
      // Never past a hero cloud: up to its box, and inside the box no further than its signed
      // distance says is clear (Nubis³'s SDF march), which it asks only where the last sample
      // was clear air (in cloud there is no jump to find); a jump shorter than half a voxel is
      // not worth its lookup, and the ray steps instead.
      if (heroCloudCount() > 0u) {  // kHeroCompiledOut
        CLOUDS_WHEN(heroHit && skipTo > t) {
          float clear = t < heroSpan.x ? heroSpan.x - t : 0.0f;
          for (int sdf = 0; sdf < (t >= heroSpan.x && !inCloud ? 1 : 0); ++sdf) {
            clear = heroField(rayDirection * t, u).clearMetres;
          }
          clear = clear > 0.5f * heroSpan.z ? clear : 0.0f;
          skipTo = min(skipTo, t + clear);
        }
      }
      if (skipTo > t) {
        t = skipTo;
        r.skippedCells += 1.0f;
        continue;
      }
    }
    const bool nearCamera = isNearStep(t, u);
    float stepLength = marchStepLength(t, inLayer ? layerEnd : end, maxSteps - samples,
                                       fine ? 1.0f : coarseFactor, u);
    if (inHero) {
      // A voxel of the finest cloud the ray meets, stretched only when its budget would not
      // reach the last box's far side.
      const float heroStep = max(heroSpan.z * kHeroStepVoxels,
                                 (heroSpan.y - t) / float(max(kMaxHeroSteps - heroSamples, 1)));
      stepLength = min(stepLength, min(heroStep, end - t));
    } else if (heroHit && t < heroSpan.x) {
      // A layer step ends at the hero clouds' box: one that ran on into it took a sample of
      // hero cloud with the layer's step length (a coarse step is 200 m at High), which made
      // the rays whose jump over an empty cell ended just short of the box opaque too soon:
      // dark lines down a hero cloud where a cell's edge meets the box's face.
      stepLength = min(stepLength, heroSpan.x - t);
    }
    const float sampleDistance = t + jitter * stepLength;
    const vec3 flatOffset = rayDirection * sampleDistance;
    const float sampleAltitude =
        altitudeAlongRay(sampleDistance, cosZenith, altitude, u.planetRadiusMetres);
    const FieldSample field = sampleField(flatOffset, sampleAltitude, sampleDistance, jitter,
                                          fine ? o.detail : 0u, 0u, u);
    r.viewSamples += 1.0f;
    if (inHero) {
      ++heroSamples;
    } else if (!nearCamera) {
      ++samples;
    }
    if (!fine && field.base > 0.0f) {
      // A coarse sample found cloud: go back one coarse step and resample it finely.
      fine = true;
      emptyRun = 0;
      continue;
    }
    // With light reuse, a cloudy sample that follows another takes its optical depth towards
    // the sun on odd iterations: the sun's path from two samples one fine step apart differs
    // by that step's share of it. The iteration's parity (not the ray's count of cloudy
    // samples) decides, so the lanes of a group skip the light samples together: on lavapipe
    // a group takes them when any of its lanes does.
    const bool reuse = o.lightReuse != 0u && inCloud && (i & 1) == 1;
    // A ray through hero clouds lit by their light volume (or its straight integral) takes their
    // own optical depth from it where a sample lies in their boxes (heroLitSun()); every other
    // ray marches the cone as it always did (a variant without hero clouds compiles only that).
    const bool heroLit = heroLightMode() != kHeroLightCone && heroHit;
    // Past the entry, the iteration's place (not the ray's count of cloudy samples) decides, so
    // that the lanes of a group read the map together, as with light reuse.
    CLOUDS_WHEN(field.sigmaT > 0.0f && (!inCloud || (i % kFarShadowEvery) == 0)) {
      farOpticalDepth = farCloudOpticalDepth(flatOffset, sampleAltitude);
    }
    CLOUDS_WHEN(field.sigmaT > 0.0f && !reuse && !heroLit) {
      // The cone up to its length, the shadow map beyond it.
      sunOpticalDepth = lightOpticalDepth(flatOffset, sampleAltitude, sampleDistance, jitter,
                                          o.lightSteps, lightRandom, 0u, u, r.lightSamples) +
                        farOpticalDepth;
    }
    if (heroLightMode() != kHeroLightCone) {  // kHeroCompiledOut
      CLOUDS_WHEN(field.sigmaT > 0.0f && !reuse && heroLit) {
        sunOpticalDepth = heroLitSun(flatOffset, sampleAltitude, sampleDistance, jitter,
                                     lightRandom, farOpticalDepth, u, o, r.lightSamples);
      }
    }
    inCloud = field.sigmaT > 0.0f;
    CLOUDS_WHEN(field.sigmaT > 0.0f) {
      const float sunLight = terrainSunLight(flatOffset, sampleAltitude);
      const vec3 light = sampleRadiance(sunOpticalDepth, sunLight, phases, field.profile,
                                        field.heightFraction, u, o.multipleScattering);
      const float stepTransmittance = beerLambert(field.sigmaT * stepLength);
      // Energy-conserving step (Hillaire 2016): the scattered light of a homogeneous step is
      // S (1 - exp(-sigma d)) / sigma with S = albedo sigma L, weighted by the transmittance.
      const float absorbed = r.transmittance * (1.0f - stepTransmittance);
      r.radiance += light * (albedo * absorbed);
      weightedDepthSum += sampleDistance * absorbed;
      if (r.frontDepth == 0.0f) r.frontDepth = sampleDistance;
      r.transmittance *= stepTransmittance;
    }
    emptyRun = field.sigmaT > 0.0f ? 0 : emptyRun + 1;
    if (o.cheapSampling != 0u && fine && emptyRun >= zeroRunToCoarse) fine = false;
    t += stepLength;
  }

  const float opacity = 1.0f - r.transmittance;
  if (r.transmittance < cutoff) {
    r.earlyExit = 1u;
    // Early exit: extrapolate the remaining light as more of the same and call it opaque.
    r.radiance /= max(opacity, 1e-6f);
    r.transmittance = 0.0f;
  }
  r.weightedDepth = opacity > 1e-6f ? weightedDepthSum / opacity : 0.0f;
  return r;
}

FX_SHADER_END

#endif
