#version 460
// The lightning bolts (FrameInputs::lightningBolts), drawn into the clouds' radiance output after
// the upsample, over the bolts' screen bounds only (a frame pays for the pixels near a bolt,
// not for the screen: on lavapipe every invocation of a pass costs, whatever it skips). Each
// piece is a line of its channel's width, keeping its energy when thinner than a pixel (a one-
// pixel tent filter across it), hidden by the host's geometry nearer than it, seen through the
// clouds as far as it lies behind their front, and hazed like them at its own distance. A pixel
// tests only the pieces binned into its tile and shows the one that covers it most. Nothing of
// it enters a history: the histories were written by the upsample before.
// Inputs: 0 CloudUniforms; 1 the host's depth; 3 the clouds' depths (output res); 4 the host's
// aerial perspective (3D, kSpecAerialPerspective); 5 the bolts' pieces (LightningBoltsHeader).
// In and out: 2 the clouds' radiance + transmittance (output res). Push constants:
// LightningBoltsConstants.
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
// 1: the host gave an aerial perspective; the bolts are hazed with it.
layout(constant_id = kSpecBoltsAerialPerspective) const uint kAerialPerspective = 0u;
layout(push_constant) uniform Constants { LightningBoltsConstants constants; };
#define CLOUDS_FRAME_UNIFORMS_INDEX constants.frameUniformsIndex
#include "frame_uniforms.glsl"
layout(binding = kBoltsHostDepth) uniform sampler2D hostDepth;
layout(binding = kBoltsRadiance, rgba16f) uniform image2D radianceImage;
layout(binding = kBoltsDepth, rg32f) uniform readonly image2D depthImage;
layout(binding = kBoltsAerialPerspective) uniform sampler3D aerialPerspective;
// Read four words at a time (one load, not four: each costs on lavapipe).
layout(binding = kBoltsPieces, std430) readonly buffer LightningBolts {
  LightningBoltsHeader bolts;
  uvec4 boltQuads[];
};

#include "fxcontracts/aerial_perspective.glsl"

#include "cloud_march.h"

// Word `word` of the buffer's words, and the four from `word` (a multiple of 4) as a vec4.
uint boltWord(uint word) { return boltQuads[word >> 2u][word & 3u]; }
vec4 boltVec4(uint word) { return uintBitsToFloat(boltQuads[word >> 2u]); }

void main() {
  loadFrameUniforms();
  uvec2 pixel = constants.origin + gl_GlobalInvocationID.xy;
  if (constants.listedBlocks != 0u) {
    const uint block = boltWord(bolts.tiles.z + gl_WorkGroupID.x);
    pixel = uvec2(block & 0xffffu, block >> 16u) * kWorkgroupSize2D + gl_LocalInvocationID.xy;
  }
  if (any(greaterThanEqual(pixel, u.outputExtent))) return;
  const vec2 p = vec2(pixel) + 0.5f;
  if (any(lessThan(p, bolts.bounds.xy)) || any(greaterThan(p, bolts.bounds.zw))) return;
  // Only the pieces binned into this pixel's tile (most tiles of a bolt's bounds have none).
  const uvec2 tile = min(uvec2((p - bolts.bounds.xy) / float(bolts.count.w)), bolts.count.yz - 1u);
  const uint range = bolts.tiles.x + 2u * (tile.y * bolts.count.y + tile.x);
  const uint pieces = boltWord(range + 1u);
  if (pieces == 0u) return;
  const uint first = bolts.tiles.y + boltWord(range);
  // The piece that covers the pixel most (its coverage times its radiance), found with no more
  // than the pieces themselves; most pixels of a tile are on none.
  float brightest = 0.0f;
  vec3 channel = vec3(0.0f);
  float inverseW = 0.0f;
  for (uint k = 0u; k < pieces; ++k) {
    const uint piece = kBoltWordsPerSegment * boltWord(first + k);
    const vec4 ends = boltVec4(piece);
    const vec4 along = boltVec4(piece + 4u);
    const vec2 ab = ends.zw - ends.xy;
    const float t = saturate(dot(p - ends.xy, ab) / max(dot(ab, ab), 1e-12f));
    const float w = mix(along.x, along.y, t);
    const float width = along.z * bolts.clipWRow.w * w;  // px
    const float across = length(p - (ends.xy + t * ab));
    const float coverage = min(width, 1.0f) * saturate(0.5f * max(width, 1.0f) + 0.5f - across);
    const vec3 light = boltVec4(piece + 8u).rgb * coverage;
    const float brightness = light.r + light.g + light.b;
    if (brightness > brightest) {
      brightest = brightness;
      channel = light;
      inverseW = w;
    }
  }
  if (brightest <= 0.0f) return;
  // Then whether it is seen: not behind the host's geometry, through the clouds as far as it
  // lies behind their front (by their depth span, as the glow takes it), and through the haze.
  const vec2 extent = vec2(u.outputExtent);
  const float scene =
      sceneDistanceFromDepth(texelFetch(hostDepth, ivec2(pixel), 0).r, p, extent, u);
  // Along the ray (m): a unit view-space ray has clip w dot(clipWRow.xyz, ray) a metre.
  const float wPerMetre = max(dot(bolts.clipWRow.xyz, viewRayDirection(p, extent, u)), 1e-6f);
  const float distance = 1.0f / (inverseW * wPerMetre);
  if (distance > scene) return;
  const vec4 clouds = imageLoad(radianceImage, ivec2(pixel));
  const vec2 depth = imageLoad(depthImage, ivec2(pixel)).xy;
  const float span = max(2.0f * (depth.y - depth.x), 1.0f);
  const float behind = depth.x > 0.0f ? saturate((distance - depth.x) / span) : 0.0f;
  float air = 1.0f;
  if (kAerialPerspective != 0u) {
    const vec4 haze = aerialPerspectiveAt(aerialPerspective, p / extent, distance,
                                          u.aerialPerspectiveRange, u.aerialPerspectiveSlices);
    air = haze.a;
  }
  imageStore(radianceImage, ivec2(pixel),
             vec4(clouds.rgb + channel * (mix(1.0f, clouds.a, behind) * air), clouds.a));
}
