// The per-frame CloudUniforms of the module's image passes (binding 0), read into the global
// `u` by loadFrameUniforms() at the top of main().
//
// Why the indirection: lavapipe "inlines" uniform-buffer values that decide a branch or a
// loop bound (constant-offset loads only) into the shader, re-optimising and re-loading it
// at every dispatch that follows a descriptor bind: about 5 ms per dispatch for the march,
// per frame, measured on Mesa 22.3. Indexing the block with a value the compiler cannot fold
// makes every load dynamically addressed, which the inliner skips. The index is a push
// constant (always 0): lavapipe loads a uniform at an offset made of push constants once for
// all lanes, where one made of anything else (gl_NumWorkGroups, as before) is gathered lane by
// lane: at 640x360 that cost the upsample 0.6 ms of its 2.4 at Medium. A storage buffer
// avoids the inliner too, but its loads are per-lane as well.
//
// A shader with push constants of its own defines CLOUDS_FRAME_UNIFORMS_INDEX to the member
// that holds the index before including this file.
#ifndef CLOUDS_FRAME_UNIFORMS_GLSL
#define CLOUDS_FRAME_UNIFORMS_GLSL

layout(binding = kBindingUniforms, std140) uniform FrameUniforms {
  CloudUniforms frameUniforms[1];
  // The C++ struct's last member (cloud_types.h says why it is not the GLSL struct's).
  WeatherRegionUniform frameWeatherRegions[kMaxWeatherRegions];
};

#ifndef CLOUDS_FRAME_UNIFORMS_INDEX
layout(push_constant) uniform FrameUniformsConstants { FrameUniformsIndex frameIndex; };
#define CLOUDS_FRAME_UNIFORMS_INDEX frameIndex.index
#endif

CloudUniforms u;

void loadFrameUniforms() { u = frameUniforms[CLOUDS_FRAME_UNIFORMS_INDEX]; }

// cloud_weather_regions.h's: read in place, never copied.
WeatherRegionUniform weatherRegion(CloudUniforms unused, uint index) {
  return frameWeatherRegions[index];
}

#endif
