// GPU-visible types and constants of the clouds module, shared by its shaders and its C++.
// std140-compatible: vec4/uvec4/mat4 members only, explicit padding, no bool.
#ifndef CLOUDS_CLOUD_TYPES_H
#define CLOUDS_CLOUD_TYPES_H

#include "clouds_interop.h"

CLOUDS_SHADER_BEGIN

// Texture sizes (powers of two: wrapping is a bit mask).
const int kShapeNoiseSize = 128;  // low-frequency 3D noise, RGBA8
const int kDetailNoiseSize = 32;  // high-frequency 3D noise, RGBA8
const int kCurlNoiseSize = 128;   // 2D curl noise, RGBA8 (RG used)
const int kWeatherMapSize = 512;  // 2D weather map, RGBA8: coverage, type, density
// Empty-space skipping: the weather map's maximum coverage (R) and type (G) over cells, at two
// levels (64 x 64 cells of 8 x 8 texels, 8 x 8 cells of 64 x 64 texels), each cell's maximum
// including a one-texel apron because the march filters the weather map bilinearly.
const int kWeatherMaxFineSize = 64;
const int kWeatherMaxCoarseSize = 8;

const uint kWorkgroupSize2D = 8u;  // 8x8 threads for image passes
const uint kWorkgroupSize3D = 4u;  // 4x4x4 threads for volume generation

// Flags in CloudUniforms.frame.z.
const uint kFlagReversedZ = 1u;    // host depth: near = 1, far/sky = 0
const uint kFlagHasDepth = 2u;     // a depth buffer is bound (else: nothing occludes)
const uint kFlagHomogeneous = 4u;  // tests: density 1 everywhere inside the layer

// Specialization constant ids of the march shader.
const uint kSpecJitter = 0u;              // 0 none, 1 Bayer 4x4 + Halton frame offset, 2 that
                                          //   and a Halton offset of the ray inside its pixel
const uint kSpecDetail = 1u;              // 0/1: high-frequency erosion compiled in
const uint kSpecCheapSampling = 2u;       // 0/1: coarse steps in empty space (Nubis switch)
const uint kSpecMultipleScattering = 3u;  // 0/1: octave multiple-scattering approximation
const uint kSpecLightSteps = 4u;          // light samples per view sample (>= 0)
const uint kSpecCounters = 5u;            // 0/1: accumulate work counters (benchmarks, tests)
const uint kSpecEmptySpace = 6u;          // 0/1: skip empty weather cells

// Specialization constant id of the reconstruction shader.
const uint kSpecHistory = 0u;  // 0 none, 1 read in place (nothing moved), 2 reprojected

// Specialization constant ids of the upsample shader.
const uint kSpecTemporalUpsampling = 0u;  // 0/1: accumulate the output-resolution history
const uint kSpecOutputHistory = 1u;       // 0 none, 1 read in place (nothing moved), 2 reprojected

// Work counters (a storage buffer of uints), reset every frame.
const uint kCounterViewSamples = 0u;   // density samples along view rays
const uint kCounterLightSamples = 1u;  // density samples towards the sun
const uint kCounterTracedPixels = 2u;  // rays marched
const uint kCounterEarlyExits = 3u;    // rays stopped by the transmittance cutoff
const uint kCounterSkippedCells = 4u;  // empty weather cells jumped over
const uint kCounterCount = 8u;

struct CloudUniforms {
  mat4 inverseProjection;  // host clip space -> view space
  mat4 viewToWorld;        // rotation only: the module works camera-relative
  vec4 planet;             // x camera altitude m, y planet radius m, z layer bottom m, w top m
  vec4 sunDirection;       // xyz unit vector towards the sun (world), w unused
  vec4 sunIlluminance;     // rgb sun illuminance (host radiometric units), w unused
  vec4 ambientTop;         // rgb sky radiance reaching cloud tops, w unused
  vec4 ambientBottom;      // rgb radiance reaching cloud bases, w unused
  vec4 shapeNoise;         // xyz camera offset inside the shape tile (m), w tile size (m)
  vec4 detailNoise;        // xyz camera offset inside the detail tile (m), w tile size (m)
  vec4 weather;            // xy camera xz inside the weather tile (m), z tile (m), w unused
  vec4 curl;               // xy camera xz inside the curl tile (m), z tile (m), w strength (m)
  vec4 wind;               // xy unit wind direction (world xz), z skew over the layer (m), w unused
  vec4 density;  // x extinction per metre at density 1, y coverage, z type, w type variation
  vec4 shape;    // x anvil bias, y detail erosion, z detail distance (m), w density variation
  vec4 phase;    // x forward g, y backward g, z backward weight, w albedo
  vec4 multipleScattering;  // x octaves, y extinction attenuation a, z contribution b, w
                            // eccentricity c
  vec4 artistic;            // x in-scatter strength, y ambient occlusion strength, z ambient, w sun
  vec4 inScatter;           // x depth (m) over which the coarse extinction gives the in-scatter
                            // probability's "density", yzw unused
  vec4 march;               // x base step m, y step growth per m, z max distance m, w T cutoff
  vec4 light;               // x light cone length m, y cone spread, z coarse factor, w zero-run
  uvec4 frame;              // x temporal index (frames since the history was reset: jitter and
                            //   update order), y max view steps, z flags, w unused
  uvec4 extent;             // xy trace extent (px), zw full extent (px)
  // --- Temporal reconstruction ------------------------------------------------------------
  mat4 previousClipFromView;  // this frame's view space -> last frame's clip space for
                              //   directions (w = 0): last view-projection x viewToWorld
  vec4 reprojection;          // xyz: where a point seen now was, relative to last frame's camera:
                              //   camera move plus the clouds' wind drift (m); w history valid 0/1
  vec4 previousClipOrigin;    // last frame's clip position of this frame's camera (with the drift)
  vec4 temporal;              // x weight of a fresh sample over its history, y clamp margin,
                              //   z trace scale (trace px per output px), w reprojection spread
                              //   (trace px) at which the history is fully clamped
  uvec4 pattern;              // x tile size k (1, 2, 4 or 8): one pixel per k x k tile is traced
                              //   each frame; y, z: that pixel's offset in the tile; w: the
                              //   last such pixel of the image, x | y << 16 (edge tiles may
                              //   have none)
  vec4 emptySpace;            // x fine cell (m), y coarse cell (m), zw unused
  vec4 subpixel;              // xy this frame's offset of the rays inside their pixels (trace
                  //   pixels, jitter mode 2; accumulating frames supersamples), zw unused
  vec4 upsampling;         // temporal upsampling: x own samples averaged before the running
                           //   mean (Settings::upsamplingMaxSamples), yzw unused
};
CLOUDS_STATIC_ASSERT(sizeof(CloudUniforms) == 3 * 64 + 27 * 16);

// Push constants of the noise generators.
struct NoiseConstants {
  uvec4 params;  // x seed, y size (texels per side), z unused, w unused
};
CLOUDS_STATIC_ASSERT(sizeof(NoiseConstants) == 16);

// Push constants of the weather generator.
struct WeatherConstants {
  vec4 params;  // x evolution phase in [0, 1), yzw unused
  uvec4 seed;   // x seed, y first row generated by this dispatch
};
CLOUDS_STATIC_ASSERT(sizeof(WeatherConstants) == 32);

// Push constants of the composite helper.
struct CompositeConstants {
  uvec4 extent;  // xy host colour extent
};
CLOUDS_STATIC_ASSERT(sizeof(CompositeConstants) == 16);

CLOUDS_SHADER_END

#endif
