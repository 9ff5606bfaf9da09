// The invocation of a 2D image pass, with its workgroups taken in a spread order.
//
// A CPU device shares a dispatch's workgroups among its threads in contiguous runs of their
// linear index (Mesa 22.3's lavapipe: one run a thread, rows of workgroups one after another),
// so the thread given the image's top rows marches the sky's clouds while the one given its
// bottom rows meets the terrain at once and waits. Here the workgroups are visited in a
// generalised bit-reversed order of their linear index: any aligned run of consecutive
// positions covers the image evenly (the first half of them is every other workgroup, each
// quarter every fourth, ...), so each thread gets its share of every part of the picture. A GPU
// hands out workgroups as its units free up and sees no difference. Every pixel is computed by
// the same code as before, so the image is the same to the bit: only which workgroup computes
// it changes. Used by the passes whose cost varies across the image (the clouds' marches).
//
// Shared with C++ (fxcontracts/shader_interop.h) so the order can be tested on the CPU.
#ifndef VKFX_SPREAD_WORKGROUPS_H
#define VKFX_SPREAD_WORKGROUPS_H

#include "fxcontracts/shader_interop.h"

FX_SHADER_BEGIN(vkfx::shader)

// The index at `position` of `count` in that order (a bijection of [0, count)): each halving
// sends the first (larger) half of the remaining positions to the even indices and the rest to
// the odd ones.
FX_INLINE uint spreadIndex(uint position, uint count) {
  uint index = 0u;
  uint stride = 1u;
  while (count > 1u) {
    const uint evens = (count + 1u) / 2u;
    if (position < evens) {
      count = evens;
    } else {
      position -= evens;
      count -= evens;
      index += stride;
    }
    stride *= 2u;
  }
  return index;
}

FX_SHADER_END

#ifndef __cplusplus
// gl_GlobalInvocationID.xy with the workgroups in the spread order, for workgroups of
// `workgroupSize` (the shader's local_size x and y: passed in, because gl_WorkGroupSize reads
// (1, 1, 1) in code that comes before the shader's layout declaration).
uvec2 spreadInvocation(uvec2 workgroupSize) {
  const uint columns = gl_NumWorkGroups.x;
  const uint group =
      spreadIndex(gl_WorkGroupID.y * columns + gl_WorkGroupID.x, columns * gl_NumWorkGroups.y);
  return uvec2(group % columns, group / columns) * workgroupSize + gl_LocalInvocationID.xy;
}
#endif

#endif
