#version 460
// Composite helper: applies the clouds over the host's colour image in place,
// colour = colour * transmittance + radiance. The march already stopped at the host's depth,
// so clouds behind geometry are absent and clouds in front cover it.
// With god rays (kSpecCompositeGodRays, vkfx/god_rays.h), then, where the pixel shows the sky
// (by the clouds' transmittance): with the host's haze, the share of the haze's in-scattering
// that the mask says is hidden from the sun is taken out, weighted by its Mie share (shafts in
// the air towards the sun); without, the fallback glow along the clear paths is added.
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(constant_id = kSpecCompositeGodRays) const uint kGodRays = 0u;
layout(binding = kCompositeHostColor, rgba16f) uniform image2D hostColor;
layout(binding = kCompositeClouds, rgba16f) uniform readonly image2D cloudRadiance;
layout(binding = kCompositeGodRayMask) uniform sampler2D godRayMask;
layout(binding = kCompositeHostDepth) uniform sampler2D hostDepth;
layout(binding = kCompositeAerialPerspective) uniform sampler3D aerialPerspective;
layout(binding = kCompositeGodRays, std140) uniform GodRays { GodRayComposite godRays; };
layout(push_constant) uniform Constants { CompositeConstants constants; };

#include "vkfx/aerial_perspective.glsl"

// The view ray through the pixel (view space, unit, through the pixel's point on the near
// plane: finite for any projection).
vec3 pixelRay(uvec2 pixel) {
  const vec2 ndc = (vec2(pixel) + 0.5f) / vec2(constants.extent) * 2.0f - 1.0f;
  const vec4 nearPoint = godRays.viewFromClip * vec4(ndc, 1.0f - godRays.maskScale.z, 1.0f);
  return normalize(nearPoint.xyz / nearPoint.w);
}

// How much of the pixel is sky seen past the clouds: the screen-space mask says nothing of the
// air in front of the host's geometry (lit or not by the sun whatever hides the sun on screen)
// nor in front of an opaque cloud, so only the air towards the sky gets shafts.
float skyShare(uvec2 pixel, float cloudTransmittance) {
  const float farPlane = godRays.maskScale.z;
  const bool hasDepth = godRays.maskScale.w > 0.5f;
  const bool sky = !hasDepth || texelFetch(hostDepth, ivec2(pixel), 0).r == farPlane;
  return sky ? cloudTransmittance : 0.0f;
}

void main() {
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, constants.extent.xy))) return;
  const vec4 clouds = imageLoad(cloudRadiance, ivec2(pixel));
  const vec4 color = imageLoad(hostColor, ivec2(pixel));
  vec3 result = color.rgb * clouds.a + clouds.rgb;
  if (kGodRays != kGodRaysNone) {
    const float cosTheta = dot(pixelRay(pixel), godRays.sunView.xyz);
    const float fade = godRays.sunView.w * skyShare(pixel, clouds.a);
    const vec2 maskUv = (vec2(pixel) + 0.5f) * godRays.maskScale.xy;
    const float clear = textureLod(godRayMask, maskUv, 0.0f).r;
    if (kGodRays == kGodRaysMaskHaze) {
      const vec2 uv = (vec2(pixel) + 0.5f) / vec2(constants.extent);
      // The air as far as the haze reaches (the sky is farther).
      const vec3 haze = aerialPerspectiveAt(aerialPerspective, uv, godRays.hazeScale.w,
                                            godRays.hazeScale.w, godRays.sunIlluminance.w)
                            .rgb *
                        godRays.hazeScale.xyz;
      const vec3 share = godRayMieShare(godRays.rayleighPerMetre.xyz,
                                        godRays.miePerMetre.xyz, godRays.rayleighPerMetre.w,
                                        cosTheta);
      result = max(result - fade * (1.0f - clear) * share * haze, vec3(0.0f));
    } else {
      result += fade * clear * godRayGlow(cosTheta, godRays.miePerMetre.w) *
                godRays.sunIlluminance.xyz;
    }
  }
  imageStore(hostColor, ivec2(pixel), vec4(result, color.a));
}
