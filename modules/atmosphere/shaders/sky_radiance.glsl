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

#endif
