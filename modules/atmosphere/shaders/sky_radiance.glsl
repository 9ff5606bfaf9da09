// The sky's radiance towards the camera along a world direction, for a sun of unit illuminance
// and without the sun's disc: the sky-view LUT (the air), plus the sunlit ground where the
// direction hits the planet. For shaders that declare `skyViewLut` and implement
// sampleTransmittance(); after loadUniforms().
#ifndef SKY_RADIANCE_GLSL
#define SKY_RADIANCE_GLSL

vec3 skyRadiance(vec3 direction, AtmosphereModel a) {
  const float r = u.cameraRadius;
  const vec2 uv = skyViewUv(direction.y, azimuthCosineFromSun(direction, u.sunDirection), r, a,
                            vec2(u.skyViewSize));
  return textureLod(skyViewLut, uv, 0.0).rgb + groundThroughAir(r, direction, u.sunDirection, a);
}

#endif
