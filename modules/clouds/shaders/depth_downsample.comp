#version 460
// Conservative scene distance at the trace resolution: each trace pixel keeps the farthest
// host geometry among the output pixels it covers (the sky is "infinitely far"), so clouds are
// marched wherever any covered pixel could see them; the upsample pass then hides them again,
// per output pixel, behind nearer geometry. Without a host depth every distance is infinite.
// Inputs: binding 0 CloudUniforms, 1 host depth (texelFetch). Output: 2 R32F distance (m).
#extension GL_GOOGLE_include_directive : require
#include "cloud_types.h"

layout(local_size_x = kWorkgroupSize2D, local_size_y = kWorkgroupSize2D) in;
#include "frame_uniforms.glsl"
layout(binding = kSceneDistanceHostDepth) uniform sampler2D hostDepth;
layout(binding = kSceneDistanceOut, r32f) uniform writeonly image2D outDistance;

#include "cloud_march.h"

// The farther of two depth values (with reversed-Z, the smaller).
float farther(float a, float b, bool reversed) { return reversed ? min(a, b) : max(a, b); }
vec2 farther(vec2 a, vec2 b, bool reversed) { return reversed ? min(a, b) : max(a, b); }

void main() {
  loadFrameUniforms();
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, u.traceExtent))) return;
  const uvec2 full = u.outputExtent;
  // The output pixels whose centres fall in this trace pixel.
  const uvec2 first = uvec2(floor(vec2(pixel) * vec2(full) / vec2(u.traceExtent)));
  const uvec2 last =
      min(uvec2(ceil(vec2(pixel + 1u) * vec2(full) / vec2(u.traceExtent))), full) - 1u;
  // The farthest depth value first, converted once: within a footprint of a few pixels the
  // distance for a depth changes with the ray's angle by well under 3%, which the margin covers.
  // Read 2 x 2 texels at a time (one gather; per-texel loads in a loop whose bounds lavapipe
  // cannot tell are the same for all lanes cost about twice as much): each block starts where
  // it lies inside the footprint, overlapping the last one where the footprint is odd, and
  // along an axis one pixel wide the block's second texel is left out.
  const bool reversed = (u.flags & kFlagReversedZ) != 0u;
  const float nearest = reversed ? 1.0f : 0.0f;  // no farther than any depth
  const vec2 texelSize = 1.0f / vec2(textureSize(hostDepth, 0));
  const bvec2 wide = greaterThan(last, first);
  const uvec2 lastCorner = max(last, first + 1u) - 1u;
  float farthestDepth = nearest;
  for (uint y = first.y; y <= last.y; y += 2u) {
    for (uint x = first.x; x <= last.x; x += 2u) {
      const uvec2 corner = min(uvec2(x, y), lastCorner);
      // Gather order: (x0, y1), (x1, y1), (x1, y0), (x0, y0).
      vec4 depths = textureGather(hostDepth, (vec2(corner) + 1.0f) * texelSize, 0);
      if (!wide.x) depths.yz = vec2(nearest);
      if (!wide.y) depths.xy = vec2(nearest);
      const vec2 pairs = farther(depths.xy, depths.zw, reversed);
      farthestDepth = farther(farthestDepth, farther(pairs.x, pairs.y, reversed), reversed);
    }
  }
  const vec2 centre = 0.5f * (vec2(first) + vec2(last + 1u));
  const float margin = all(equal(first, last)) ? 1.0f : 1.03f;
  const float farthest = sceneDistanceFromDepth(farthestDepth, centre, vec2(full), u) * margin;
  imageStore(outDistance, ivec2(pixel), vec4(farthest, 0.0f, 0.0f, 0.0f));
}
