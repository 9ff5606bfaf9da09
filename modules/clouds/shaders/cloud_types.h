// GPU-visible types and constants of the clouds module, shared by its shaders and its C++:
// texture sizes, workgroup sizes, descriptor binding slots, specialization-constant ids, the
// per-frame uniform block and the push-constant blocks. The shaders use these names in their
// layout qualifiers and the C++ binds with them, so a slot or size is written once.
//
// Layout rules: std140 (the uniform block) and push constants; fields are scalars, vec2/uvec2
// on 8-byte offsets, vec3 + one scalar or vec4 on 16-byte offsets, mat4 on 64, explicit
// padding, no bool (uint flags). The C++ side asserts every offset; a unit test checks them
// against glslang's reflection of the GLSL block.
#ifndef CLOUDS_CLOUD_TYPES_H
#define CLOUDS_CLOUD_TYPES_H

#include "fxcontracts/cloud_shadow.h"
#include "fxcontracts/god_rays.h"
#include "fxcontracts/shader_interop.h"

FX_SHADER_BEGIN(clouds::shader)

// --- Texture sizes (powers of two: wrapping is a bit mask) ----------------------------------
const int kShapeNoiseSize = 128;  // low-frequency 3D noise, RGBA8 packed (cloud_sampling.h)
const int kDetailNoiseSize = 32;  // high-frequency 3D noise, RGBA8 packed (cloud_sampling.h)
// The 3D noises keep their whole mip chain, down to 1 texel (the mean), in one storage image
// of n x n x 3n/2 texels (noiseLevelOrigin() in cloud_sampling.h says where each level lies).
const int kShapeNoiseLevels = 8;   // 128^3 .. 1^3
const int kDetailNoiseLevels = 6;  // 32^3 .. 1^3
// The hero clouds' detail noise (cloud_noise.h's heroNoiseTexel()): four channels, not packed
// (cloud_hero.h blends them per sample), its whole chain in one n x n x 5n/4 image
// (cloud_hero.h's heroNoiseTexelAddress()).
const int kHeroNoiseSize = 128;
const int kHeroNoiseLevels = 8;  // 128^3 .. 1^3
const int kHeroNoiseDepth = kHeroNoiseSize + kHeroNoiseSize / 4;
const int kCurlNoiseSize = 128;   // 2D curl noise, RGBA8 (RG used)
const int kWeatherMapSize = 512;  // 2D weather map, RGBA8: coverage, type, density
// Empty-space skipping: the weather map's maximum coverage (R) and type (G) over cells, at two
// levels (64 x 64 cells of 8 x 8 texels, 8 x 8 cells of 64 x 64 texels), each cell's maximum
// including a one-texel apron because the march filters the weather map bilinearly.
const int kWeatherMaxFineSize = 64;
const int kWeatherMaxCoarseSize = 8;

// --- Workgroup sizes -------------------------------------------------------------------------
const uint kWorkgroupSize2D = 8u;     // 8 x 8 threads for image passes
const uint kWorkgroupSize3D = 4u;     // 4 x 4 x 4 threads for volume generation
const uint kSkyAmbientLanes = 64u;    // sky_ambient.comp: one workgroup of this many lanes
const uint kSkyAmbientSamples = 16u;  // samples of the sky image per lane
// The sky light (Settings::skyLight): an equirectangular map of the sky with the clouds in it,
// laid out as the host's sky image (u = azimuth, v = 0 at the zenith, 0.5 at the horizon, 1 at
// the nadir). The clouds of its upper half are marched one texel in each 2 x 2 block a frame.
const uint kSkyLightWidth = 64u;
const uint kSkyLightHeight = 32u;
const uint kSkyLightLanes = 64u;      // sky_light.comp: one workgroup of this many lanes
const uint kSkyLightEveryTexel = 4u;  // CloudUniforms.skyLightRefresh: the whole upper half

// --- Descriptor bindings (set 0) --------------------------------------------------------------
// Binding 0 of every per-frame image pass is the CloudUniforms block (frame_uniforms.glsl).
const uint kBindingUniforms = 0u;
// depth_downsample.comp: the host depth in, the conservative scene distance out.
const uint kSceneDistanceHostDepth = 1u;
const uint kSceneDistanceOut = 2u;
// cloud_march.comp
const uint kMarchShapeNoise = 1u;
const uint kMarchDetailNoise = 2u;
const uint kMarchWeatherMap = 3u;
const uint kMarchCurlNoise = 4u;
const uint kMarchSceneDistance = 5u;
const uint kMarchSamplesOut = 6u;
const uint kMarchWeatherMaxFine = 7u;
const uint kMarchWeatherMaxCoarse = 8u;
const uint kMarchCounters = 9u;
const uint kMarchCloudShadow = 10u;            // the shadow map, sampled (kSpecShadowMapRead)
const uint kMarchCloudShadowParameters = 11u;  // its CloudShadowParameters (uniform block)
const uint kMarchTraceHistory = 12u;  // last frame's reconstruction (edge rays: kSpecEdgeRays)
const uint kMarchEdgeRayList = 13u;   // the edge rays' tiles and dispatch (kSpecEdgeRays)
// Hero clouds (kSpecHeroClouds): their atlas (RGBA8 3D, hero_clouds.h) and this frame's
// instances (HeroCloudUniforms). Without hero clouds, stand-ins: the shape noise and the frame's
// uniforms, which the march then never reads.
const uint kMarchHeroAtlas = 14u;
const uint kMarchHeroClouds = 15u;
// Their light volume (R16F 3D, hero_light_volume.comp; kSpecHeroLight kHeroLightVolume); a
// stand-in otherwise: the scene distance, which the march then never reads there.
const uint kMarchHeroLight = 16u;
// Their detail noise (kHeroNoiseSize chain, RGBA8); the shape noise stands in without them.
const uint kMarchHeroNoise = 17u;
// The near field's samples (kSpecNearField's pass writes them; RGBA32UI, nearFieldExtent).
const uint kMarchNearFieldOut = 18u;
// The sky light's clouds (kSpecSkyLight's pass writes them; RGBA16F, kSkyLightWidth x
// kSkyLightHeight / 2: radiance, transmittance).
const uint kMarchSkyLightOut = 19u;
// reconstruct.comp
const uint kReconstructFresh = 1u;
const uint kReconstructHistory = 2u;
const uint kReconstructOut = 3u;
const uint kReconstructFlashes = 4u;        // LightningUniforms (a stand-in without lightning)
const uint kReconstructGlow = 5u;           // RGBA16F glow per unit of cloud (lightningFlashes > 0)
const uint kReconstructSceneDistance = 6u;  // the scene distance image (R32F, trace res)
// near_field_resolve.comp (after the near field's march; packed samples, nearFieldExtent).
const uint kNearResolveFresh = 1u;    // this frame's near field
const uint kNearResolveHistory = 2u;  // last frame's resolved near field
const uint kNearResolveOut = 3u;      // this frame's resolved near field
// upsample.comp
const uint kUpsampleTraceSamples = 1u;
const uint kUpsampleHostDepth = 2u;
const uint kUpsampleRadianceOut = 3u;
const uint kUpsampleDepthOut = 4u;
const uint kUpsampleFresh = 5u;
const uint kUpsampleHistory = 6u;
const uint kUpsampleHistoryOut = 7u;
const uint kUpsampleAerialPerspective = 8u;  // the host's haze (FrameInputs::aerialPerspective)
const uint kUpsampleLightningGlow = 10u;     // reconstruct.comp's glow (lightningFlashes > 0)
const uint kUpsampleGodRayLight = 9u;        // god_rays.comp's light (Settings::godRaySamples > 0)
const uint kUpsampleNearField = 11u;         // the near field's samples (kSpecUpsampleNearField)
// cloud_shadow_map.comp (binding 0: the CloudUniforms of the frame the map is made in)
const uint kShadowShapeNoise = 1u;
const uint kShadowWeatherMap = 2u;
const uint kShadowWeatherMaxFine = 3u;
const uint kShadowWeatherMaxCoarse = 4u;
const uint kShadowMapOut = 5u;    // the cascade atlas (fxcontracts/cloud_shadow.h), RGBA16F
const uint kShadowMapSpare = 6u;  // one cascade in the making (kShadowTexelToSpare), RGBA16F
// Hero clouds (kSpecShadowHeroClouds), as the march's kMarchHeroAtlas and kMarchHeroClouds.
const uint kShadowHeroAtlas = 7u;
const uint kShadowHeroClouds = 8u;
const uint kShadowHeroNoise = 9u;
// hero_light_volume.comp: the hero atlas and this frame's instances in, the light volume out.
const uint kLightSweepAtlas = 0u;
const uint kLightSweepClouds = 1u;
const uint kLightSweepVolume = 2u;
const uint kLightSweepNoise = 3u;
// terrain_shadow_map.comp
const uint kTerrainShadowHeight = 0u;  // the host's heightfield, sampled
const uint kTerrainShadowMap = 1u;     // the cascade atlas: its terrain channel is written
// composite.comp
const uint kCompositeHostColor = 0u;
const uint kCompositeClouds = 1u;
// lightning_bolts.comp (binding 0: the frame's CloudUniforms)
const uint kBoltsHostDepth = 1u;
const uint kBoltsRadiance = 2u;           // the clouds' radiance output, read and written
const uint kBoltsDepth = 3u;              // the clouds' depths output
const uint kBoltsAerialPerspective = 4u;  // the host's haze (a placeholder without one)
const uint kBoltsPieces = 5u;             // LightningBoltsHeader and its words
// god_ray_occlusion.comp (binding 0: the frame's CloudUniforms)
const uint kGodRayTraceSamples = 1u;   // the reconstructed trace image (packed)
const uint kGodRaySceneDistance = 2u;  // the conservative scene distance (trace res)
const uint kGodRayOcclusionOut = 3u;   // the occlusion image, R32F
const uint kGodRayNearField = 4u;      // the near field resolved (kSpecGodRayNearField)
// god_rays.comp
const uint kGodRayOcclusion = 0u;  // the occlusion image, sampled (linear, clamped)
const uint kGodRayMaskOut = 1u;    // the mask, R32F
const uint kGodRayHaze = 2u;       // the host's haze, sampled (a placeholder without one)
const uint kGodRayUniforms = 3u;   // GodRayLightUniforms (uniform block)
const uint kGodRayLightOut = 4u;   // RGBA16F: what the composite adds to a sky pixel
// sky_ambient.comp (reads and writes the uniforms as a storage buffer)
const uint kSkyAmbientUniforms = 0u;
const uint kSkyAmbientSky = 1u;           // the host's sky image (a placeholder without one)
const uint kSkyAmbientShadowMap = 2u;     // the cloud shadow map (a placeholder without one)
const uint kSkyAmbientLastSkyLight = 3u;  // the last frame's SkyLightMeasures, or a placeholder
// sky_light.comp (reads the uniforms as a uniform block at kBindingUniforms)
const uint kSkyLightHostSky = 1u;           // the host's sky image
const uint kSkyLightClouds = 2u;            // the clouds marched towards the upper half's texels
const uint kSkyLightShadowMap = 3u;         // the cloud shadow map (a placeholder without one)
const uint kSkyLightMap = 4u;               // the map made (RGBA16F)
const uint kSkyLightMeasures = 5u;          // SkyLightMeasures (storage buffer, read by the host)
const uint kSkyLightShadowParameters = 6u;  // the shadow map's MarchShadowMap (uniform block)
// noise_*.comp, hero_noise*.comp and weather_procedural.comp: the texture they generate
// (noise_mip.comp, hero_noise_mip.comp: the 3D noise whose mip chain they complete)
const uint kGeneratorTarget = 0u;
// weather_resample.comp: the module's weather map from the host's painted one
const uint kResampleTarget = 0u;
const uint kResampleSource = 1u;
const uint kResampleBlendSource = 2u;
// weather_max.comp: one level of the maxima from the level below
const uint kMaximaSource = 0u;
const uint kMaximaTarget = 1u;

// --- Specialization constants ----------------------------------------------------------------
// cloud_march.comp
const uint kSpecJitter = 0u;              // 0 none, 1 Bayer 4x4 + Halton frame offset, 2 that
                                          //   and a Halton offset of the ray inside its pixel
const uint kSpecDetail = 1u;              // 0/1: high-frequency erosion compiled in
const uint kSpecCheapSampling = 2u;       // 0/1: coarse steps in empty space (Nubis switch)
const uint kSpecMultipleScattering = 3u;  // 0/1: octave multiple-scattering approximation
const uint kSpecLightSteps = 4u;          // light samples per view sample (>= 0)
const uint kSpecCounters = 5u;            // 0/1: accumulate work counters (benchmarks, tests)
const uint kSpecEmptySpace = 6u;          // 0/1: skip empty weather cells
const uint kSpecShadowMapRead = 7u;       // kShadowMapReads* bits: what of this frame's shadow
                                          //   map takes the sun from clouds
const uint kSpecLightReuse = 8u;          // 0/1: the sun's optical depth on every other step
const uint kSpecEdgeRays = 9u;            // kEdgeRays*: more rays for tiles on silhouettes
const uint kSpecHeroClouds = 10u;         // kHeroClouds*: hero clouds (FrameInputs::heroClouds)
const uint kSpecHeroLight = 11u;          // kHeroLight*: how hero clouds shadow themselves
const uint kSpecNearField = 12u;          // 0/1: the near field's pass (every pixel of its
                                          //   image, the ray up to the split)
const uint kSpecWeatherRegions = 13u;     // Settings::weatherRegions: the regions a frame may
                                          //   have (0: no region code)
const uint kSpecVortex = 14u;             // Settings::superstorms: 0/1, the vortex code
const uint kSpecSkyLight = 15u;           // 0/1: the sky light's pass (the map's upper half's
                                          //   rays due this frame, to the layer's far side)
const uint kMarchSpecCount = 16u;
// The bits of kSpecShadowMapRead: the terrain's channel (the terrain's shadow on the clouds),
// the clouds' own beyond the light cone (Settings::cloudShadowsOnClouds).
const uint kShadowMapReadsTerrain = 1u;
const uint kShadowMapReadsClouds = 2u;
// The variants of kSpecEdgeRays: none; the tiles' march, which lists the edge tiles; the
// edge rays' march, over that list (an indirect dispatch).
const uint kEdgeRaysOff = 0u;
const uint kEdgeRaysFind = 1u;
const uint kEdgeRaysMarch = 2u;
const uint kEdgeRayListHeaderBytes = 16u;  // cloud_march.comp's EdgeRayList before its tiles
const uint kMaxEdgeRaysPerTile = 2u;       // Settings::edgeRays; slots in a tile: edgeRaySlot()
// reconstruct.comp
const uint kSpecHistory = 0u;  // 0 none, 1 read in place (nothing moved), 2 reprojected
const uint kSpecReconstructLightning = 1u;  // 0/1: write the glow with this frame's flashes
const uint kReconstructSpecCount = 2u;
// near_field_resolve.comp:
const uint kSpecNearHistory = 0u;  // 0/1: last frame's resolved near field is usable
const uint kNearResolveSpecCount = 1u;
// upsample.comp
const uint kSpecTemporalUpsampling = 0u;   // 0/1: accumulate the output-resolution history
const uint kSpecOutputHistory = 1u;        // 0 none, 1 read in place (nothing moved), 2 reprojected
const uint kSpecAerialPerspective = 2u;    // 0/1: haze the output (FrameInputs::aerialPerspective)
const uint kSpecUpsampleGodRays = 3u;      // 0/1: add god_rays.comp's light to the sky's pixels
const uint kSpecUpsampleLightning = 4u;    // 0/1: the clouds glow with LightningUniforms' flashes
const uint kSpecUpsampleDepthOutput = 5u;  // 0/1: store the cloud depth output
const uint kSpecUpsampleNearField = 6u;    // 0/1: lay the near field's samples over the far part
const uint kUpsampleSpecCount = 7u;
// lightning_bolts.comp
const uint kSpecBoltsAerialPerspective = 0u;  // 0/1: haze them (FrameInputs::aerialPerspective)
const uint kBoltsSpecCount = 1u;
// god_ray_occlusion.comp
const uint kSpecGodRayNearField = 0u;  // 0/1: the near field's transmittance hides the sun too
const uint kGodRayOcclusionSpecCount = 1u;
// god_rays.comp
const uint kSpecGodRayLight = 0u;  // kGodRaysMaskHaze or kGodRaysGlow
const uint kGodRaySpecCount = 1u;
const uint kGodRaysMaskHaze = 1u;  // the haze's Mie in-scattering, masked
const uint kGodRaysGlow = 2u;      // the fallback without a haze: a glow along the clear paths
// cloud_shadow_map.comp
const uint kSpecShadowEmptySpace = 0u;      // 0/1: skip empty weather cells
const uint kSpecShadowHeroClouds = 1u;      // kHeroClouds*: hero clouds cast into the map too
const uint kSpecShadowWeatherRegions = 2u;  // as the march's kSpecWeatherRegions
const uint kSpecShadowVortex = 3u;          // as the march's kSpecVortex
const uint kShadowSpecCount = 4u;
// The history variants of kSpecHistory and kSpecOutputHistory.
const uint kHistoryNone = 0u;
const uint kHistoryInPlace = 1u;
const uint kHistoryReprojected = 2u;

// --- Flags in CloudUniforms.flags ------------------------------------------------------------
const uint kFlagReversedZ = 1u;    // host depth: near = 1, far/sky = 0
const uint kFlagHasDepth = 2u;     // a depth buffer is bound (else: nothing occludes)
const uint kFlagHomogeneous = 4u;  // tests: density 1 everywhere inside the layer
// A frame without history, the camera in or near the layer or a hero cloud: its rays spread their
// start offsets over the tiles (rayJitter), and it is rebuilt from them by a tent
// (reconstruct.comp).
const uint kFlagRebuiltInsideCloud = 8u;
// This frame marches edge rays (Settings::edgeRays, with an output history to keep them):
// pixels of each tile hold its edge rays' samples, or kNoEdgeRay (edgeRaySlot()).
const uint kFlagEdgeRays = 16u;

// --- Work counters (a storage buffer of uints, reset every frame) ----------------------------
const uint kCounterViewSamples = 0u;    // density samples along view rays
const uint kCounterLightSamples = 1u;   // density samples towards the sun
const uint kCounterTracedPixels = 2u;   // rays marched
const uint kCounterEarlyExits = 3u;     // rays stopped by the transmittance cutoff
const uint kCounterSkippedCells = 4u;   // empty weather cells jumped over
const uint kCounterEdgeRays = 5u;       // edge rays marched (also counted as rays marched)
const uint kCounterNearFieldRays = 6u;  // the near field's rays (not counted as rays marched)
const uint kCounterCount = 8u;

// --- The per-frame uniform block --------------------------------------------------------------
// One weather region (FrameInputs::weatherRegions) as the shaders read it: where it lies,
// relative to the camera, and the look inside.
const uint kMaxWeatherRegions = 8u;
struct WeatherRegionUniform {
  vec4 placement;  // xy its centre (camera-relative x, z m), zw its core's half sides (m)
  vec4 shape;      // xy its x axis (world x, z; unit), z the core's rounding radius (m), w the
                   //   blend distance (m, > 0)
  vec4 look;       // x coverage, y cloud type, z density scale (as layerDensityScale), w anvils
  vec4 vortex;     // a superstorm's (cloud_vortex.h): x the eye's radius (m; 0: none), y the
                   //   eye wall's width (m), z the turn's rate at the wall's middle (rad/s,
                   //   counter-clockwise seen from above), w spiral arms
};
// CloudUniforms.vortexRegion without a superstorm.
const uint kNoVortex = 0xffffffffu;

// Built on the CPU once per frame (src/uniforms.cpp) from the host's inputs and the settings.
// Positions are camera-relative: the tiling offsets are reduced modulo their tile in double
// precision on the CPU, so the GPU only sees small numbers.
struct CloudUniforms {
  // Camera.
  mat4 inverseProjection;     // host clip space -> view space
  mat4 viewToWorld;           // rotation only: the module works camera-relative
  mat4 previousClipFromView;  // this frame's view directions (w = 0) -> last frame's clip
                              //   space: the history's view-projection x viewToWorld
  vec4 previousClipOrigin;    // last frame's clip position of this frame's camera, with the
                              //   clouds' wind drift since (reprojection, cloud_temporal.h)

  // Planet and layer (m).
  float cameraAltitudeMetres;
  float planetRadiusMetres;
  float layerBottomMetres;
  float layerTopMetres;

  // Light, in the host's units: illuminance for the sun, radiance for the ambient sky.
  vec3 sunDirection;  // unit vector towards the sun (world)
  // How far the camera moved through the air (m) since the frame the history was made in
  // (reconstruct.comp: history of air it flew through is not reprojected as is).
  float cameraMovedMetres;
  vec3 sunIlluminance;
  float sunStrength;  // scales the direct sun term
  vec3 ambientTop;    // sky radiance reaching cloud tops (sky_ambient.comp may overwrite it)
  float ambientStrength;
  vec3 ambientBottom;  // radiance reaching cloud bases (sky_ambient.comp may overwrite it)
  float ambientOcclusionStrength;

  // Noise and weather placement: the camera's offset inside each tile, and the tile (m).
  vec3 shapeOffsetMetres;
  float shapeTileMetres;
  vec3 detailOffsetMetres;
  float detailTileMetres;
  vec2 weatherOffsetMetres;  // camera xz inside the weather tile (coverage does not scroll)
  float weatherTileMetres;
  float noiseFootprintPerMetre;  // the noise's level of detail: texel width (m) whose level a
                                 //   sample reads per metre of distance (0: the finest always)
  vec2 curlOffsetMetres;
  float curlTileMetres;
  float curlStrengthMetres;  // swirl of the detail noise at the cloud base
  vec2 windDirection;        // unit, world xz
  float skewMetres;          // downwind lean across the layer
  // The near/far split this frame (Settings::nearFieldMetres; 0: none): the march's tiles
  // start their rays here, the near field's pass ends its rays here (MarchOptions::nearField).
  float nearFieldMetres;
  float fineCellMetres;    // empty-space skipping: side of a fine weather-maxima cell
  float coarseCellMetres;  //   and of a coarse one
  uvec2 nearFieldExtent;   // px: the near field's images (nearFieldExtentFor())

  // Density model.
  float extinctionPerMetre;  // at density 1, times Settings::densityMultiplier
  float coverage;
  float cloudType;
  float typeVariation;
  float anvilBias;
  float detailErosion;
  float detailDistanceMetres;
  float densityVariation;

  // Lighting.
  float phaseForwardG;
  float phaseBackwardG;
  float phaseBackwardWeight;
  float albedo;
  float msOctaves;  // multiple-scattering octaves, as a float
  float msExtinctionScale;
  float msContribution;
  float msEccentricityScale;
  float inScatterStrength;
  float inScatterCoreProfile;  // the coarse profile that counts as a cloud's core
  float silverIntensity;       // the silver-lining lobe's scale (0: the lobes' mix alone)
  float silverG;               // its HG g (0.99 - Settings::silverSpread)

  // Ray-march.
  float viewStepMetres;
  float viewStepGrowth;  // extra step length per metre of distance
  float maxDistanceMetres;
  float transmittanceCutoff;
  float lightConeMetres;
  float lightConeSpread;
  float coarseStepFactor;
  float emptySamplesToCoarse;
  uint temporalIndex;  // frames since the history was reset: jitter and update order
  uint maxViewSteps;
  uint flags;            // kFlag*
  float rayStartOffset;  // [0, 1): where this frame's rays start in their first step, before
                         //   each pixel's own term (rayJitter(); refreshStartOffset())

  // Resolution and temporal reconstruction.
  uvec2 traceExtent;    // px
  uvec2 outputExtent;   // px
  uvec2 tilePhase;      // the offset, in its tile, of the pixel marched this frame
  uint tileSize;        // k (1, 2, 4 or 8): one pixel per k x k tile is marched each frame
  uint lastFreshPixel;  // the last such pixel of the image, x | y << 16 (edge tiles may have none)
  float temporalFreshWeight;       // weight of a fresh sample over its history
  float historyClampMargin;        // slack of the history clamp (x neighbourhood range)
  float traceScale;                // trace pixels per output pixel
  float historyClampSpreadPixels;  // reprojection spread (trace px) of a fully clamped history
  vec2 subpixelOffset;         // this frame's offset of the rays inside their pixels (trace pixels;
                               //   jitter mode 2: accumulating frames supersamples)
  float upsamplingMaxSamples;  // temporal upsampling: own samples averaged before a running mean
  uint lightRound;             // the round of refreshes this frame's rays belong to: it rotates
                               //   their light samples' cone (lightJitter())

  // The host's aerial perspective (fxcontracts/aerial_perspective.glsl), when it gives one.
  vec3 aerialPerspectiveScale;    // multiplies the volume's radiance
  float aerialPerspectiveRange;   // m, the distance of its last slice
  float aerialPerspectiveSlices;  // its depth in slices
  // Edge rays (kFlagEdgeRays): how many per edge tile, and where each starts in its first step
  // (as rayStartOffset for this frame's other rays; x the first, y the second).
  uint edgeRaysPerTile;
  vec2 edgeRayStartOffsets;

  // 1 / the integral over the sphere of each multiple-scattering octave's phase (octaves 0-3,
  // 4-7): the silver lining's max() gains energy that these give back (silverLiningPhase()).
  vec4 phaseNormaliserInverseLow;
  vec4 phaseNormaliserInverseHigh;

  // Edge rays: where each sits in its trace pixel (as subpixelOffset for this frame's other
  // rays; xy the first, zw the second).
  vec4 edgeSubpixelOffsets;

  // The wind's turn from the layer's base to its top (radians, counter-clockwise seen from
  // above; Settings::windShearDegrees): the skew follows it (noisePosition()).
  float windShearRadians;
  // Weather regions (FrameInputs::weatherRegions, cloud_weather_regions.h): how many, and the
  // look around them. The layer's extinction is u.extinctionPerMetre x a column's density
  // scale: the surrounding weather's is layerDensityScale (1 without regions), a region's its
  // own; extinctionPerMetre then holds the densest multiplier of them all.
  uint weatherRegionCount;
  float layerDensityScale;
  float fullestCoverage;  // the largest coverage of the surrounding weather and the regions
  // A camera-relative world offset (w = 0) -> last frame's clip space: the history's
  // view-projection (its rotation only). The superstorm's reprojection moves a point by the
  // storm's turn with it (cloud_temporal.h).
  mat4 previousClipFromWorld;
  // The superstorm (cloud_vortex.h): its flow phases' clocks (x, y: seconds since each phase
  // restarted, each under the period), z the first phase's weight (the second's is 1 - z), w
  // unused; the region it is (kNoVortex: none); and how long ago (s) the history's frame was,
  // by which its reprojection turns a point back (0: plain).
  vec4 vortexClock;
  uint vortexRegion;
  float vortexHistorySeconds;
  // The sky light's texels marched this frame (Settings::skyLight): in each 2 x 2 block of its
  // upper half the one at (refresh & 1, refresh >> 1), or kSkyLightEveryTexel for all of them.
  uint skyLightRefresh;
  float padding0;
#ifdef __cplusplus
  // The regions themselves: in C++ the struct's last member; in GLSL the frame block's member
  // after the struct (frame_uniforms.glsl), at the same offset, read in place by
  // weatherRegion(). Why not in the GLSL struct: the passes copy the struct into a private `u`
  // and into every function that takes it, and a dynamically indexed array in that copy puts
  // it in scratch memory: the march took 3.6 times as long on lavapipe, regions or not.
  WeatherRegionUniform weatherRegions[kMaxWeatherRegions];
#endif
};

// Push constants of sky_ambient.comp: which sources the frame has, and the ground's albedo.
const uint kAmbientFromSkyImage = 1u;  // the sky image replaces ambientTop and ambientBottom
const uint kAmbientGroundLight = 2u;   // bases see the ground (groundAlbedo)
const uint kAmbientGroundShadow = 4u;  // ... in the clouds' shadow (the shadow map's mean)
const uint kAmbientFromSkyLight = 8u;  // bases see the last frame's sky light (the clouds in it)
struct AmbientConstants {
  vec3 groundAlbedo;    // Lambertian, [0, 1] per channel
  uint flags;           // kAmbient* bits
  uint shadowCascades;  // cascades side by side in the shadow map (cascade 0 is read)
  uint shadowTexels;    // texels per cascade side
  uint padding0;
  uint padding1;
};

// Push constants of sky_light.comp: the frame's sources and the ground's albedo.
const uint kSkyLightCloudsMarched = 1u;  // the clouds image holds this frame's sky (else clear)
const uint kSkyLightGround = 2u;         // the ground below is lit from the map (groundAlbedo)
const uint kSkyLightGroundShadow = 4u;   // ... in the clouds' shadow (the shadow map's mean)
const uint kSkyLightSunAtCamera = 8u;    // the shadow map is this frame's: read it at the camera
struct SkyLightConstants {
  vec3 groundAlbedo;        // Lambertian, [0, 1] per channel
  uint flags;               // kSkyLight* bits
  uint shadowCascades;      // cascades side by side in the shadow map (cascade 0 is read)
  uint shadowTexels;        // texels per cascade side
  uint frameUniformsIndex;  // always 0 (frame_uniforms.glsl says why)
  uint padding0;
};

// What sky_light.comp measures of its map, for the host (Context::skyLighting()): radiances
// (rgb), the regions' means by solid angle.
struct SkyLightMeasures {
  vec4 upperIrradianceOverPi;  // the upper hemisphere weighted by the cosine to the zenith (x pi:
                               //   a horizontal surface's irradiance); a: its luminance
  vec4 zenith;                 // above 60 degrees of elevation
  vec4 horizon;                // from the horizon up to 10 degrees
  vec4 lower;                  // the lower hemisphere
  vec4 clearIrradianceOverPi;  // the host's sky alone, as upperIrradianceOverPi
  // Where the map was seen from, for a meter at the camera: x the clouds' transmittance of the
  // sun at the camera (the shadow map's, 1 without one), y the altitude (m) the upper half was
  // seen from (skyLightAltitude()), z the altitude above which no layer cloud is (m), w the
  // share of the ground around the camera in the sun (the shadow map's finest cascade's mean, 1
  // without one).
  vec4 viewpoint;
};

// Push constants of noise_mip.comp: packs level 0 of a 3D noise (one of four passes, by the
// parity of x and y) or makes `level` of its chain from the level above.
struct NoiseMipConstants {
  uint size;    // texels per side of level 0
  uint level;   // the level made; 0: pack level 0
  uint parity;  // level 0: the texels packed in this pass, x & 1 | (y & 1) << 1
  uint padding0;
};

// Push constants of the noise generators.
struct NoiseConstants {
  uint seed;
  uint size;  // texels per side
  uint padding0;
  uint padding1;
};

// Push constants of the weather generator.
struct WeatherConstants {
  float evolutionPhase;  // in [0, 1)
  uint seed;
  uint firstRow;  // the first row this dispatch generates
  uint padding0;
};

// Push constants of the painted map's resampling: the weight of the second painting.
struct ResampleConstants {
  float blend;  // [0, 1]
  uint padding0;
  uint padding1;
  uint padding2;
};

// Push constants of the weather maxima (one level from the level below).
struct MaximaConstants {
  uint sourceSize;  // texels per side of the source
  uint cellSize;    // source texels per side of a target cell
  uint targetSize;  // cells per side
  uint padding0;
};

// Push constants of the shadow map: the cascade one dispatch makes (cloud_shadow_march.h).
struct ShadowMapConstants {
  vec4 axisU;        // xyz U (unit), w: u of texel 0's centre (m, camera-relative)
  vec4 axisV;        // xyz V (unit), w: v of texel 0's centre
  vec4 light;        // xyz L, the direction the rays go (unit, towards the sun), w texel size (m)
  ivec2 worldTexel;  // texel 0's index on the cascade's world grid (the jitter's seed)
  uint cascade;      // which cascade of the atlas
  uint resolution;   // texels per cascade side
  uint steps;        // samples along each ray
  uint flags;        // kShadowTexelKeepTerrain, kShadowTexelToSpare
  uint firstRow;     // the rows [firstRow, firstRow + rowCount) are made
  uint rowCount;
};
// ShadowMapConstants::flags. Keep terrain: the cascade's terrain channel (alpha) in the atlas
// is still right (same rays, same terrain): keep it; else write "no terrain"
// (terrain_shadow_map.comp follows when there is one). To spare: write the texels into the
// spare cascade image (a cascade made over several frames) instead of the atlas.
const uint kShadowTexelKeepTerrain = 1u;
const uint kShadowTexelToSpare = 2u;

// The march's uniform block for the shadow map it reads (kMarchCloudShadowParameters): the map's
// lookup parameters, and the terrain's highest altitude (no sample above it can be in the
// terrain's shadow: the march does not look).
#ifdef __cplusplus
using fxcontracts::shader::CloudShadowParameters;
#endif
struct MarchShadowMap {
  CloudShadowParameters map;
  float terrainTopMetres;
  float padding0;
  float padding1;
  float padding2;
};

// Push constants of the terrain's shadow (terrain_shadow_march.h): the cascade, and where the
// host's heightfield lies.
struct TerrainShadowConstants {
  ShadowMapConstants cascade;
  vec2 heightOriginMetres;  // the heightfield's (0, 0) corner, camera-relative (x, z)
  vec2 heightInverseSize;   // 1 / its extent along x and z (1/m)
  float minAltitudeMetres;  // the terrain's lowest and highest altitude
  float maxAltitudeMetres;
  float biasMetres;  // subtracted from the stored altitude (fxcontracts/cloud_shadow.h)
  uint steps;        // heightfield samples along each ray
  float cameraAltitudeMetres;
  uint padding0;
  uint padding1;
  uint padding2;
};

// Push constants of the trace passes (scene distance, march, reconstruct, upsample): which
// element of frame_uniforms.glsl's block to read, always 0 (why: frame_uniforms.glsl).
struct FrameUniformsIndex {
  uint index;
};

// Push constants of the composite helper.
struct CompositeConstants {
  uvec2 extent;  // host colour extent (px)
  uvec2 padding0;
};

#ifdef __cplusplus
using fxcontracts::shader::GodRayParameters;  // god_rays.comp's push constants
using fxcontracts::shader::kGodRayDownsample;
#endif

// The flashes the clouds glow with this frame (reconstruct.comp, kReconstructFlashes), a uniform
// block: flash i is flash[2 i] (xyz camera-relative position (m), w radius (m)) and
// flash[2 i + 1] (rgb radiance, w unused).
const uint kMaxLightningFlashes = 16u;
struct LightningUniforms {
  uvec4 count;  // x the flashes this frame
  vec4 flash[2 * kMaxLightningFlashes];
};

// This frame's hero clouds (FrameInputs::heroClouds), a uniform block of the march. Each maps
// camera-relative metres to index coordinates of its asset's voxels (voxel centres at integers)
// by the rows of `toIndex`; its asset lies in the atlas from the texel `extent.w` codes.
const uint kMaxHeroClouds = 8u;
// An atlas origin's code: x x stride + z, exact in a float for atlases up to 4096 texels a side.
const uint kHeroAtlasOriginBits = 12u;
const uint kHeroAtlasOriginStride = 1u << kHeroAtlasOriginBits;
struct HeroCloudInstance {
  vec4 toIndex[3];  // index coordinate a = dot(toIndex[a].xyz, relative) + toIndex[a].w
  // xyz the asset's voxels per axis, w its first texel in the atlas: x x kHeroAtlasOriginStride
  // + z (cloud_hero.h's heroAtlasOrigin())
  vec4 extent;
  // x the density the fields' 1 stands for (NvdfVolume::densityMultiplier, faded as the cloud
  // dissipates); y the world metres its life erodes from its edge inwards; z the world metres
  // of one voxel; w its life's top, an index y (cloud_hero.h's heroLifeWeight())
  vec4 scales;
};
// The hero-cloud variants of the march and the shadow map (kSpecHeroClouds,
// kSpecShadowHeroClouds): none; hero clouds as authored; and some living (growing or
// dissipating), whose life the field then weighs (cloud_hero.h's heroLifeWeight()): a march
// with that code in it is slower on lavapipe even where it skips it.
const uint kHeroCloudsOff = 0u;
const uint kHeroCloudsAuthored = 1u;
const uint kHeroCloudsLiving = 2u;
// The atlas's distance code's full scale, in voxels of its asset: the longest jump one lookup
// allows (hero_clouds.h encodes, cloud_hero.h decodes).
const float kHeroDistanceRangeVoxels = 16.0f;
// A growing cloud's top fades over this fraction of its box's height (heroLifeWeight()).
const float kHeroTopFeather = 0.2f;
struct HeroCloudUniforms {
  // x the instances this frame; y their slots in the light volume (Settings::heroLight
  // Volume), kHeroLightSlotBits each, instance 0's lowest; z a slot's extent in texels,
  // x | y << 10 | z << 20 (cloud_hero_light.h's heroLightSlotOrigin()); w the detail
  // (Settings::heroDetail: kHeroDetail*)
  uvec4 count;
  HeroCloudInstance instance[kMaxHeroClouds];
};

// How a sample in a hero cloud's box learns the optical depth towards the sun through that
// cloud (Settings::heroLight, cloud_hero_light.h): the light cone through every density
// source, as the layer's samples (Nubis³'s "base"); the cloud's light volume, one lookup, with
// the cone through everything else; or the straight integral marched at half a voxel, which
// the volume approximates (the Reference).
const uint kHeroLightCone = 0u;
const uint kHeroLightVolume = 1u;
const uint kHeroLightMarched = 2u;
// What a hero cloud's voxels become between their centres (Settings::heroDetail): the
// dimensional profile as filtered, density linear in it (what OpenVDB's renderer shows of the
// same grid); or up-rezzed by the detail noise to half a metre (Nubis³'s density sampler,
// cloud_hero.h's heroUprezzedDensity()).
const uint kHeroDetailOff = 0u;
const uint kHeroDetailUprezzed = 1u;
// The detail noise's tile along each of a cloud's axes (world m): kHeroNoiseSize texels of half
// a metre.
const float kHeroNoiseTileMetres = 64.0f;
// Asset voxels per light-volume texel along each axis.
const float kHeroLightTexelVoxels = 2.0f;
const uint kHeroLightSlotBits = 3u;  // kMaxHeroClouds slots
// hero_light_volume.comp's push constants: which of this frame's instances it sweeps.
struct HeroLightConstants {
  vec4 sunDirection;  // xyz world, unit, towards the sun
  uint instances;     // bit i: sweep instance i into its slot
  uint blockIndex;    // 0: the hero block is indexed by it (frame_uniforms.glsl says why)
  uint pad0;
  uint pad1;
};

// lightning_bolts.comp's push constants: whether its workgroups are the 8 x 8 pixel blocks
// listed in the buffer (the blocks of the tiles that hold pieces), or, when those are too many
// to list, a grid over the bolts' bounds from `origin` (output pixels).
struct LightningBoltsConstants {
  uvec2 origin;
  uint listedBlocks;        // 0/1
  uint frameUniformsIndex;  // always 0 (frame_uniforms.glsl)
};

// The bolts' pieces on screen (lightning_bolts.comp, kBoltsPieces), a storage buffer the
// module projects FrameInputs::lightningBolts into each frame: this header, then 32-bit words.
// Piece i is the kBoltWordsPerSegment words from kBoltWordsPerSegment i, three vec4s in output
// pixels (y down, as the shaders' pixels):
//   [0] xy one end, zw the other;
//   [1] x, y 1 / the ends' clip w (linear on screen, so interpolated exactly along the
//       piece), z the glowing channel's width (m), w unused;
//   [2] rgb the channel's radiance, w unused.
// The pieces are binned into square tiles from `bounds.xy` (so a pixel tests only the pieces
// near it): tile (x, y), t = y columns + x, has the pieces whose indices are words
// [tiles.y + first, tiles.y + first + n), first and n the words tiles.x + 2 t and + 1. The
// tiles that hold pieces are listed as 8 x 8 pixel blocks, x | y << 16 in blocks, from word
// tiles.z, tiles.w of them (none when more than kBoltMaxBlocks).
struct LightningBoltsHeader {
  uvec4 count;    // x the pieces on screen this frame; y, z the tiles' columns and rows; w a
                  //   tile's side (px, a multiple of 8)
  uvec4 tiles;    // x the first word of the tiles' ranges, y that of the pieces' indices, z
                  //   that of the blocks, w how many blocks
  vec4 bounds;    // xy the tiles' origin (a multiple of 8 px) at or below the lowest output
                  //   pixel any piece covers, zw the highest
  vec4 clipWRow;  // xyz the projection's w row (a view-space ray's clip w per metre along
                  //   it), w the focal length (px): a width at clip w is width focal / w px
};
const uint kBoltWordsPerSegment = 12u;
// At most this many tiles and pieces' indices in them (coarser tiles when more would be needed).
const uint kBoltMaxTiles = 1024u;
const uint kBoltMaxTileIndices = 4096u;
const uint kBoltMaxBlocks = 4096u;

// god_ray_occlusion.comp's push constants.
struct GodRayOcclusionConstants {
  uvec2 maskExtent;         // texels: the render extent over kGodRayDownsample, rounded up
  uint frameUniformsIndex;  // always 0 (frame_uniforms.glsl)
  uint padding0;
};

// The god rays' light (fxcontracts/god_rays.h's uses: god_rays.comp makes it per mask texel, the
// upsample adds it to the sky's pixels), a uniform block.
struct GodRayLightUniforms {
  mat4 viewFromClip;  // the host's inverse projection: a pixel's view-space position
  vec4 sunView;       // xyz the direction towards the sun in view space, w the fade f
  // xy the mask's uv per screen uv (the mask may reach past the render extent), z the depth of
  // the host's near plane (1 with reversed-Z, else 0), w unused
  vec4 screenScale;
  vec4 rayleighPerMetre;  // xyz the air's Rayleigh scattering at the ground, w Mie's g
  vec4 miePerMetre;       // xyz the air's Mie scattering at the ground, w the glow's strength
  vec4 hazeScale;         // xyz the haze's radiance scale, w its range (m)
  vec4 sunIlluminance;    // xyz (the fallback's glow), w the haze's slices
};

FX_SHADER_END

#ifdef __cplusplus
#include <cstddef>
// std140 offsets, asserted where the C++ compiler lays the struct out (glm types have the
// sizes GLSL has, but not std140's alignment: these catch a field that would move).
#define CLOUDS_ASSERT_OFFSET(type, field, offset) \
  static_assert(offsetof(clouds::shader::type, field) == (offset), #type "." #field)
CLOUDS_ASSERT_OFFSET(CloudUniforms, viewToWorld, 64);
CLOUDS_ASSERT_OFFSET(CloudUniforms, previousClipFromView, 128);
CLOUDS_ASSERT_OFFSET(CloudUniforms, previousClipOrigin, 192);
CLOUDS_ASSERT_OFFSET(CloudUniforms, cameraAltitudeMetres, 208);
CLOUDS_ASSERT_OFFSET(CloudUniforms, sunDirection, 224);
CLOUDS_ASSERT_OFFSET(CloudUniforms, sunIlluminance, 240);
CLOUDS_ASSERT_OFFSET(CloudUniforms, sunStrength, 252);
CLOUDS_ASSERT_OFFSET(CloudUniforms, ambientTop, 256);
CLOUDS_ASSERT_OFFSET(CloudUniforms, ambientBottom, 272);
CLOUDS_ASSERT_OFFSET(CloudUniforms, shapeOffsetMetres, 288);
CLOUDS_ASSERT_OFFSET(CloudUniforms, detailOffsetMetres, 304);
CLOUDS_ASSERT_OFFSET(CloudUniforms, weatherOffsetMetres, 320);
CLOUDS_ASSERT_OFFSET(CloudUniforms, curlOffsetMetres, 336);
CLOUDS_ASSERT_OFFSET(CloudUniforms, windDirection, 352);
CLOUDS_ASSERT_OFFSET(CloudUniforms, fineCellMetres, 368);
CLOUDS_ASSERT_OFFSET(CloudUniforms, extinctionPerMetre, 384);
CLOUDS_ASSERT_OFFSET(CloudUniforms, anvilBias, 400);
CLOUDS_ASSERT_OFFSET(CloudUniforms, phaseForwardG, 416);
CLOUDS_ASSERT_OFFSET(CloudUniforms, msOctaves, 432);
CLOUDS_ASSERT_OFFSET(CloudUniforms, inScatterStrength, 448);
CLOUDS_ASSERT_OFFSET(CloudUniforms, viewStepMetres, 464);
CLOUDS_ASSERT_OFFSET(CloudUniforms, lightConeMetres, 480);
CLOUDS_ASSERT_OFFSET(CloudUniforms, temporalIndex, 496);
CLOUDS_ASSERT_OFFSET(CloudUniforms, traceExtent, 512);
CLOUDS_ASSERT_OFFSET(CloudUniforms, outputExtent, 520);
CLOUDS_ASSERT_OFFSET(CloudUniforms, tilePhase, 528);
CLOUDS_ASSERT_OFFSET(CloudUniforms, tileSize, 536);
CLOUDS_ASSERT_OFFSET(CloudUniforms, temporalFreshWeight, 544);
CLOUDS_ASSERT_OFFSET(CloudUniforms, subpixelOffset, 560);
CLOUDS_ASSERT_OFFSET(CloudUniforms, upsamplingMaxSamples, 568);
CLOUDS_ASSERT_OFFSET(CloudUniforms, aerialPerspectiveScale, 576);
CLOUDS_ASSERT_OFFSET(CloudUniforms, aerialPerspectiveRange, 588);
CLOUDS_ASSERT_OFFSET(CloudUniforms, aerialPerspectiveSlices, 592);
CLOUDS_ASSERT_OFFSET(CloudUniforms, edgeRaysPerTile, 596);
CLOUDS_ASSERT_OFFSET(CloudUniforms, edgeRayStartOffsets, 600);
CLOUDS_ASSERT_OFFSET(CloudUniforms, phaseNormaliserInverseLow, 608);
CLOUDS_ASSERT_OFFSET(CloudUniforms, phaseNormaliserInverseHigh, 624);
CLOUDS_ASSERT_OFFSET(CloudUniforms, edgeSubpixelOffsets, 640);
CLOUDS_ASSERT_OFFSET(CloudUniforms, windShearRadians, 656);
CLOUDS_ASSERT_OFFSET(CloudUniforms, weatherRegionCount, 660);
CLOUDS_ASSERT_OFFSET(CloudUniforms, layerDensityScale, 664);
CLOUDS_ASSERT_OFFSET(CloudUniforms, fullestCoverage, 668);
CLOUDS_ASSERT_OFFSET(CloudUniforms, previousClipFromWorld, 672);
CLOUDS_ASSERT_OFFSET(CloudUniforms, vortexClock, 736);
CLOUDS_ASSERT_OFFSET(CloudUniforms, vortexRegion, 752);
CLOUDS_ASSERT_OFFSET(CloudUniforms, vortexHistorySeconds, 756);
CLOUDS_ASSERT_OFFSET(CloudUniforms, weatherRegions, 768);
static_assert(sizeof(clouds::shader::WeatherRegionUniform) == 64);
static_assert(sizeof(clouds::shader::CloudUniforms) == 768 + 64 * 8);
static_assert(sizeof(clouds::shader::NoiseConstants) == 16);
static_assert(sizeof(clouds::shader::NoiseMipConstants) == 16);
static_assert(sizeof(clouds::shader::AmbientConstants) == 32);
static_assert(sizeof(clouds::shader::SkyLightConstants) == 32);
static_assert(sizeof(clouds::shader::SkyLightMeasures) == 6 * 16);
static_assert(sizeof(clouds::shader::WeatherConstants) == 16);
static_assert(sizeof(clouds::shader::ResampleConstants) == 16);
static_assert(sizeof(clouds::shader::MaximaConstants) == 16);
static_assert(sizeof(clouds::shader::CompositeConstants) == 16);
static_assert(sizeof(clouds::shader::FrameUniformsIndex) == 4);
static_assert(sizeof(clouds::shader::GodRayOcclusionConstants) == 16);
static_assert(sizeof(clouds::shader::LightningUniforms) == 16 + 32 * 16);
static_assert(sizeof(clouds::shader::LightningBoltsHeader) == 4 * 16);
static_assert(sizeof(clouds::shader::LightningUniforms) <= sizeof(clouds::shader::CloudUniforms),
              "without lightning the frame's uniforms stand in for its block");
static_assert(sizeof(clouds::shader::GodRayLightUniforms) == 64 + 6 * 16);
static_assert(sizeof(clouds::shader::HeroCloudInstance) == 5 * 16);
static_assert(sizeof(clouds::shader::HeroCloudUniforms) <= sizeof(clouds::shader::CloudUniforms),
              "without hero clouds the frame's uniforms stand in for their block");
static_assert(sizeof(clouds::shader::HeroLightConstants) == 32);
static_assert(clouds::shader::kMaxHeroClouds <= 1u << clouds::shader::kHeroLightSlotBits &&
              clouds::shader::kMaxHeroClouds * clouds::shader::kHeroLightSlotBits <= 32u);
static_assert(sizeof(clouds::shader::ShadowMapConstants) == 80);
static_assert(sizeof(clouds::shader::TerrainShadowConstants) == 128);
static_assert(sizeof(clouds::shader::MarchShadowMap) == 14 * 16);
#undef CLOUDS_ASSERT_OFFSET
#endif

#endif
