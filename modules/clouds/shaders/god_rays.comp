#version 460
// God rays, second pass (fxcontracts/god_rays.h): the mask, and the light the composite adds to the
// sky's pixels. Each texel averages the occlusion image at GodRayParameters' samples on its way
// towards the sun on screen, their weights decaying (Mitchell 2007): 1 where the air along its
// pixels' rays sees the sun past everything on screen, lower in the shadows clouds and
// mountains cast through the air. Then the light the upsample adds to the sky seen through the
// texel: with the host's haze (kGodRaysMaskHaze), minus the hidden part of the haze's Mie
// in-scattering; without (kGodRaysGlow), plus the fallback's glow along the clear paths. Both
// are smooth over the screen but for the mask, so a quarter resolution holds them; the upsample
// reads them filtered.
// Inputs: 0 the occlusion image (sampled, linear, clamped); 2 the host's haze (sampled); 3
// GodRayLightUniforms; push constants GodRayParameters. Outputs: 1 the mask (R32F, the
// module's Outputs::godRayMask), 4 the light (RGBA16F).
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(constant_id = kSpecGodRayLight) const uint kLight = kGodRaysMaskHaze;

layout(binding = kGodRayOcclusion) uniform sampler2D occlusion;
layout(binding = kGodRayMaskOut, r32f) uniform writeonly image2D mask;
layout(binding = kGodRayHaze) uniform sampler3D aerialPerspective;
layout(binding = kGodRayUniforms, std140) uniform GodRays { GodRayLightUniforms godRays; };
layout(binding = kGodRayLightOut, rgba16f) uniform writeonly image2D light;
layout(push_constant) uniform Constants { GodRayParameters p; };

float fetchGodRayOcclusion(vec2 uv) { return textureLod(occlusion, uv, 0.0f).r; }

#include "fxcontracts/aerial_perspective.glsl"

void main() {
  const uvec2 texel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(texel, uvec2(p.blur.zw)))) return;
  const vec2 uv = (vec2(texel) + 0.5f) / p.blur.zw;
  const float clear = godRayMaskAt(uv, p);
  imageStore(mask, ivec2(texel), vec4(clear));

  // The view ray through the texel's centre (through its point on the near plane: finite for
  // any projection) and its angle to the sun.
  const vec2 screen = uv / godRays.screenScale.xy;
  const vec4 nearPoint =
      godRays.viewFromClip * vec4(screen * 2.0f - 1.0f, godRays.screenScale.z, 1.0f);
  const float cosTheta = dot(normalize(nearPoint.xyz / nearPoint.w), godRays.sunView.xyz);
  const float fade = godRays.sunView.w;
  vec3 change;
  if (kLight == kGodRaysMaskHaze) {
    // The air as far as the haze reaches (the sky is farther).
    const float range = godRays.hazeScale.w;
    const vec3 haze = aerialPerspectiveAt(aerialPerspective, screen, range, range,
                                          godRays.sunIlluminance.w)
                          .rgb *
                      godRays.hazeScale.xyz;
    const vec3 share = godRayMieShare(godRays.rayleighPerMetre.xyz, godRays.miePerMetre.xyz,
                                      godRays.rayleighPerMetre.w, cosTheta);
    change = -fade * (1.0f - clear) * share * haze;
  } else {
    change = fade * clear * godRayGlow(cosTheta, godRays.miePerMetre.w) *
             godRays.sunIlluminance.xyz;
  }
  imageStore(light, ivec2(texel), vec4(change, 0.0f));
}
