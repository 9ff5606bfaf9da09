// The per-frame AtmosphereUniforms (binding kBindingUniforms), read into the global `u` by
// loadUniforms() at the top of main(), and the model they describe.
//
// Why the dynamically indexed block: lavapipe "inlines" uniform-buffer values that decide a
// branch or a loop bound into the shader and re-optimises it at every dispatch after a
// descriptor bind (measured by the clouds module at ~5 ms a dispatch); indexing the block with
// a value the compiler cannot fold makes the loads dynamic, which the inliner skips. In compute
// shaders the index is a push constant (always 0), which lavapipe loads once for all lanes (as
// the clouds' frame_uniforms.glsl explains); the sky's draw uses the instance index.
#ifndef ATMOSPHERE_UNIFORMS_GLSL
#define ATMOSPHERE_UNIFORMS_GLSL

layout(binding = kBindingUniforms, std140) uniform Uniforms {
  AtmosphereUniforms frameUniforms[1];
};

AtmosphereUniforms u;

// Compute shaders index with a push constant; the sky's draw (a graphics pipeline, which has
// no workgroups) defines ATMOSPHERE_GRAPHICS and indexes with the instance index, also 0.
#ifndef ATMOSPHERE_GRAPHICS
layout(push_constant) uniform UniformsIndex { uint uniformsIndex; };
void loadUniforms() { u = frameUniforms[uniformsIndex]; }
#endif
void loadUniformsAt(uint zero) { u = frameUniforms[zero]; }

AtmosphereModel modelOf(AtmosphereUniforms v) {
  AtmosphereModel a;
  a.bottomRadius = v.bottomRadius;
  a.topRadius = v.topRadius;
  a.rayleighScattering = v.rayleighScattering;
  a.rayleighScaleHeight = v.rayleighScaleHeight;
  a.mieScattering = v.mieScattering;
  a.mieAbsorption = v.mieAbsorption;
  a.mieScaleHeight = v.mieScaleHeight;
  a.miePhaseG = v.miePhaseG;
  a.ozoneAbsorption = v.ozoneAbsorption;
  a.ozoneCentre = v.ozoneCentre;
  a.ozoneHalfWidth = v.ozoneHalfWidth;
  a.groundAlbedo = v.groundAlbedo;
  return a;
}

// The view direction (world, unit) through a pixel centre of a `size` image.
vec3 viewDirection(vec2 pixelCentre, vec2 size) {
  const vec2 ndc = pixelCentre / size * 2.0 - 1.0;
  const bool reversed = (u.flags & kFlagReversedZ) != 0u;
  const vec4 view = u.inverseProjection * vec4(ndc, reversed ? 1.0 : 0.0, 1.0);
  return normalize((u.viewToWorld * vec4(view.xyz / view.w, 0.0)).xyz);
}

#endif
