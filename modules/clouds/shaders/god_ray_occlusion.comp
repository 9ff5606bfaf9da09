#version 460
// God rays, first pass (fxcontracts/god_rays.h): the occlusion image at a quarter of the render
// extent per axis, made from the reconstructed trace image before the upsample. Each texel is
// the mean, over the trace pixels its 4 x 4 output pixels fall in, of the clouds'
// transmittance where the scene distance is infinite (sky) and 0 on the host's geometry: what
// the air towards each pixel shows of the sun's light, before the radial blur. The scene
// distance is conservative (a trace pixel on a horizon counts as sky), so occluders' edges
// thin by up to a trace pixel.
// With the near/far split (kSpecGodRayNearField) the trace image holds the far part of each
// ray: the transmittance is its times the near field's at the trace pixel (nearest texel), as
// the upsample lays one over the other.
// Inputs: 0 CloudUniforms, 1 the reconstructed trace image (packed: cloud_temporal.h), 2 the
// scene distance (R32F, trace res), 4 the near field resolved (packed, half trace res); push
// constants GodRayOcclusionConstants. Output: 3 the occlusion image (R32F).
#extension GL_GOOGLE_include_directive : require
#include "cloud_temporal.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
layout(constant_id = kSpecGodRayNearField) const uint kNearField = 0u;
layout(push_constant) uniform Constants { GodRayOcclusionConstants c; };
#define CLOUDS_FRAME_UNIFORMS_INDEX c.frameUniformsIndex
#include "frame_uniforms.glsl"
layout(binding = kGodRayTraceSamples, rgba32ui) uniform readonly uimage2D traceSamples;
layout(binding = kGodRaySceneDistance, r32f) uniform readonly image2D sceneDistance;
layout(binding = kGodRayOcclusionOut, r32f) uniform writeonly image2D occlusion;
layout(binding = kGodRayNearField, rgba32ui) uniform readonly uimage2D nearField;

#include "cloud_march.h"

void main() {
  loadFrameUniforms();
  const uvec2 texel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(texel, c.maskExtent))) return;
  // The trace pixels whose centres fall in the texel's output pixels (at least one).
  const vec2 tracePerOutput = vec2(u.traceExtent) / vec2(u.outputExtent);
  const vec2 from = vec2(texel * kGodRayDownsample) * tracePerOutput;
  const vec2 to = vec2((texel + 1u) * kGodRayDownsample) * tracePerOutput;
  const uvec2 first = min(uvec2(ceil(from - 0.5f)), u.traceExtent - 1u);
  const uvec2 last = max(min(uvec2(ceil(to - 0.5f)), u.traceExtent) - 1u, first);
  float clear = 0.0f;
  float pixels = 0.0f;
  for (uint y = first.y; y <= last.y; ++y) {
    for (uint x = first.x; x <= last.x; ++x) {
      const bool sky = imageLoad(sceneDistance, ivec2(x, y)).r >= kInfiniteDistance;
      float transmittance = unpackCloudRadiance(imageLoad(traceSamples, ivec2(x, y))).a;
      if (kNearField != 0u) {
        const uvec2 near = min(uvec2((vec2(x, y) + 0.5f) * vec2(u.nearFieldExtent) /
                                     vec2(u.traceExtent)),
                               u.nearFieldExtent - 1u);
        transmittance *= unpackCloudRadiance(imageLoad(nearField, ivec2(near))).a;
      }
      clear += sky ? transmittance : 0.0f;
      pixels += 1.0f;
    }
  }
  imageStore(occlusion, ivec2(texel), vec4(clear / max(pixels, 1.0f)));
}
