// The share of the ground around the camera in the sun (GLSL only): the mean sun transmittance
// of the cloud shadow map's finest cascade, for passes that light the ground with the clouds'
// shade in it (sky_ambient.comp, sky_light.comp). The includer declares the map's sampler
// (fxcontracts/cloud_shadow_sampled.glsl) first.
#ifndef CLOUDS_CLOUD_GROUND_SUNLIT_GLSL
#define CLOUDS_CLOUD_GROUND_SUNLIT_GLSL

// An altitude below every cloud (m): the ground receives the whole ray's optical depth.
const float kBelowEveryCloudMetres = -1.0e6f;

// The sun transmittance to the ground at `uv` in the finest of `cascades` cascades of `texels`
// per side.
float groundSunlit(uint cascades, uint texels, vec2 uv) {
  const vec4 info = vec4(float(cascades), float(texels), 0, 0);
  return exp(
      -cloudShadowCascadeSample(info, 0.0f, uv, kBelowEveryCloudMetres, kCloudShadowClouds).x);
}

#endif
