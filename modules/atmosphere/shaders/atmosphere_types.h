// GPU-visible types and constants of the atmosphere module, shared by its shaders and its C++:
// workgroup sizes, descriptor binding slots, specialization-constant ids and the per-frame
// uniform block (std140: scalars, vec3 + one scalar on 16-byte offsets, explicit padding, no
// bool; the C++ asserts every offset).
#ifndef ATMOSPHERE_TYPES_H
#define ATMOSPHERE_TYPES_H

#include "fxcontracts/shader_interop.h"

FX_SHADER_BEGIN(atmosphere::shader)

// --- Sizes ----------------------------------------------------------------------------------
const uint kWorkgroupSize2D = 8u;    // 8 x 8 threads for image passes
const uint kEnvironmentWidth = 64u;  // the equirectangular sky-radiance output
const uint kEnvironmentHeight = 32u;
const uint kEnvironmentLanes = 256u;  // environment.comp: one workgroup, 8 texels a lane

// --- Descriptor bindings (set 0) ---------------------------------------------------------------
// One numbering for every pass; each pass declares the bindings it uses.
const uint kBindingUniforms = 0u;           // AtmosphereUniforms (atmosphere_uniforms.glsl)
const uint kBindingTransmittance = 1u;      // the transmittance LUT, sampled
const uint kBindingMultiScattering = 2u;    // the multiple-scattering LUT, sampled
const uint kBindingSkyView = 3u;            // the sky-view LUT, sampled
const uint kBindingAerialPerspective = 4u;  // the aerial-perspective froxels, sampled
const uint kBindingTarget = 5u;             // the storage image a pass writes
const uint kBindingHostDepth = 6u;          // apply.comp: the host's depth, sampled
const uint kBindingSkyLighting = 7u;        // environment.comp: SkyLighting, host-visible
const uint kBindingCloudShadow = 8u;  // aerial_perspective.comp: the cloud shadow map, sampled
const uint kBindingCloudShadowParameters = 9u;  // ... and its CloudShadowParameters

// --- Specialization constants -------------------------------------------------------------------
const uint kSpecHasDepth = 0u;   // apply.comp: 0 every pixel is sky, 1 the host's depth is bound
const uint kSpecReversedZ = 1u;  // apply.comp, sky_draw.vert: 1 the far plane is depth 0, else 1
const uint kApplySpecCount = 2u;

// --- Flags in AtmosphereUniforms.flags ----------------------------------------------------------
const uint kFlagReversedZ = 1u;    // host depth: near = 1, far/sky = 0
const uint kFlagCloudShadow = 2u;  // FrameInputs::cloudShadow: the air is shadowed by it

// The aerial-perspective froxels: slice s (texel centre) lies at distance
// range * ((s + 0.5) / slices)^2 along each pixel's ray, so slices are dense near the camera;
// a distance d samples the texture at w = sqrt(d / range).

struct AtmosphereUniforms {
  // Camera (this frame's, camera-relative).
  mat4 inverseProjection;  // host clip space -> view space
  mat4 viewToWorld;        // rotation only
  mat4 clipToWorldRay;     // viewToWorld * inverseProjection: a pixel's (ndc, far, 1) -> ray

  // The model (atmosphere_model.h), per metre and in metres.
  vec3 rayleighScattering;
  float rayleighScaleHeight;
  vec3 mieScattering;
  float mieScaleHeight;
  vec3 mieAbsorption;
  float miePhaseG;
  vec3 ozoneAbsorption;
  float ozoneCentre;
  vec3 groundAlbedo;
  float ozoneHalfWidth;
  float bottomRadius;
  float topRadius;
  float cameraRadius;       // the camera's distance from the planet's centre
  float sunAngularRadius;   // radians
  vec3 sunDirection;        // unit, towards the sun (world)
  float sunRadiusVersine;   // 1 - cos(the sun's angular radius), computed in double
  vec3 sunIlluminance;      // at the top of the atmosphere, host units
  float maxRadiance;        // the sun disc is clamped to this (half-float targets)
  vec3 sunDiscIlluminance;  // sunIlluminance * the transmittance from the camera to the sun
  float horizonDip;         // radians the horizon lies below the level (horizonDip())

  // LUT sizes and sample counts (Settings).
  uvec2 transmittanceSize;
  uint transmittanceSamples;
  uint multiScatteringSize;
  uint multiScatteringDirections;  // per axis: this squared directions
  uint multiScatteringSamples;
  uvec2 skyViewSize;
  uint skyViewSamples;
  uint flags;                    // kFlag*
  uvec2 outputExtent;            // px
  uvec4 aerialPerspectiveSize;   // xyz froxels, w samples per slice
  float aerialPerspectiveRange;  // m
  float padding0;
  float padding1;
  float padding2;
};

// What environment.comp measures of the sky for the host (read back once a frame completes):
// radiance in host units, averaged over solid angle.
struct SkyLighting {
  vec4 meanUpper;  // rgb: the upper hemisphere's mean radiance; a: its mean luminance
  vec4 zenith;     // rgb: the cap within 30 degrees of the zenith
  vec4 horizon;    // rgb: the band up to 10 degrees above the horizon
  vec4 lower;      // rgb: the lower hemisphere (ground and the air in front of it)
};

// Push constants of the LUT passes that need none: none. Of apply.comp: none (uniforms).

FX_SHADER_END

#ifdef __cplusplus
#include <cstddef>
#define ATMOSPHERE_ASSERT_OFFSET(type, field, offset) \
  static_assert(offsetof(atmosphere::shader::type, field) == (offset), #type "." #field)
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, viewToWorld, 64);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, clipToWorldRay, 128);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, rayleighScattering, 192);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, mieScattering, 208);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, mieAbsorption, 224);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, ozoneAbsorption, 240);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, groundAlbedo, 256);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, bottomRadius, 272);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, sunDirection, 288);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, sunIlluminance, 304);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, maxRadiance, 316);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, sunDiscIlluminance, 320);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, horizonDip, 332);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, transmittanceSize, 336);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, multiScatteringDirections, 352);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, skyViewSize, 360);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, skyViewSamples, 368);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, outputExtent, 376);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, aerialPerspectiveSize, 384);
ATMOSPHERE_ASSERT_OFFSET(AtmosphereUniforms, aerialPerspectiveRange, 400);
static_assert(sizeof(atmosphere::shader::AtmosphereUniforms) == 416);
static_assert(sizeof(atmosphere::shader::SkyLighting) == 64);
#undef ATMOSPHERE_ASSERT_OFFSET
#endif

#endif
