// The per-frame CloudUniforms of the module's image passes (binding 0), read into the global
// `u` by loadFrameUniforms() at the top of main().
//
// Why the indirection: lavapipe "inlines" uniform-buffer values that decide a branch or a
// loop bound (constant-offset loads only) into the shader, re-optimising and re-loading it
// at every dispatch that follows a descriptor bind: about 5 ms per dispatch for the march,
// per frame, measured on Mesa 22.3. Indexing the block with a value the compiler cannot fold
// (the dispatch depth minus one, always 0 here: every pass dispatches one layer) makes every
// load dynamically addressed, which the inliner skips, while the loads stay uniform (scalar).
// A storage buffer avoids the inliner too, but its loads are per-lane and cost more than the
// inlining saved (measured: the upsample and reconstruct twice as slow at 640x360).
#ifndef CLOUDS_FRAME_UNIFORMS_GLSL
#define CLOUDS_FRAME_UNIFORMS_GLSL

layout(binding = kBindingUniforms, std140) uniform FrameUniforms {
  CloudUniforms frameUniforms[1];
};

CloudUniforms u;

void loadFrameUniforms() { u = frameUniforms[gl_NumWorkGroups.z - 1u]; }

#endif
