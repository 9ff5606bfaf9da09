// The sky's radiance towards the camera along a world direction, for a sun of unit illuminance
// and without the sun's disc: the sky-view LUT (the air, and the sunlit ground where the
// direction hits the planet). For shaders that declare `skyViewLut`; after loadUniforms().
#ifndef SKY_RADIANCE_GLSL
#define SKY_RADIANCE_GLSL

vec3 skyRadiance(vec3 direction) {
  const vec2 uv = skyViewUv(direction.y, azimuthCosineFromSun(direction, u.sunDirection),
                            u.horizonDip, vec2(u.skyViewSize));
  return textureLod(skyViewLut, uv, 0.0).rgb;
}

// The sky towards `direction` in the host's units, with the sun's disc seen through the air (its
// centre's transmittance, a per-frame constant: across the half-degree disc it barely changes),
// clamped to what the host's colour holds.
vec3 skyWithSun(vec3 direction) {
  const vec3 fromSun = direction - u.sunDirection;
  const float disc = sunDiscRadiance(0.5 * dot(fromSun, fromSun), u.sunRadiusVersine);
  const vec3 radiance = skyRadiance(direction) * u.sunIlluminance + disc * u.sunDiscIlluminance;
  return min(radiance, vec3(u.maxRadiance));
}

#endif
