// The aerial-perspective volume, the contract between the module that makes it (the atmosphere)
// and every pass that hazes something with it (the atmosphere's own render pass over a host's
// geometry, the clouds' upsample): one definition of its layout and of how it is read, so that
// far clouds fade into the horizon exactly as far terrain does.
//
// A 3D texture: x and y the screen of this frame's camera (u, v = pixel centre / extent), and
// slice s (texel centres at w = (s + 0.5) / slices) the air between the camera and the distance
// rangeMetres * w^2 along each pixel's ray: slices crowd near the camera, where haze changes
// fastest. rgb is the radiance the air scatters towards the camera per unit of the producer's
// radiance scale (the atmosphere's: the sun's illuminance at the top of the atmosphere), a the
// transmittance (mean of the channels). Linear filtering, clamped to the edges.
#ifndef FX_AERIAL_PERSPECTIVE_GLSL
#define FX_AERIAL_PERSPECTIVE_GLSL

// The haze between the camera and `distanceMetres` along the ray through `uv`: rgb the
// in-scattered radiance (times the producer's radiance scale), a the transmittance. Distances
// past the last slice read the last slice; nearer than the first slice's centre the haze fades
// linearly from none at the camera.
vec4 aerialPerspectiveAt(sampler3D volume, vec2 uv, float distanceMetres, float rangeMetres,
                         float slices) {
  const float w = sqrt(max(distanceMetres, 0.0) / rangeMetres);
  const float weight = clamp(w * slices * 2.0, 0.0, 1.0);
  const vec4 haze = textureLod(volume, vec3(uv, min(w, 1.0)), 0.0);
  return vec4(haze.rgb * weight, mix(1.0, haze.a, weight));
}

#endif
