// The terrain's surface lighting, shared by its fog and aerial-perspective variants: albedo from
// the mesh's vertex colours (rock/grass/snow), the sun (Lambert) times the share of it the
// shadows let through, and a hemisphere sky ambient. HDR, linear (kcd/m^2). Needs `frame`
// (SceneFrame) declared by the includer.
#ifndef TERRAIN_LIGHTING_GLSL
#define TERRAIN_LIGHTING_GLSL

vec3 terrainLit(vec3 albedo, vec3 normal, float sunVisibility) {
  const float kInvPi = 0.318309886f;
  const vec3 n = normalize(normal);
  const float cosine = max(dot(n, frame.sunDirection.xyz), 0.0f);
  const vec3 direct = frame.sunIlluminance.rgb * (cosine * kInvPi * sunVisibility);
  const vec3 upperSky = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, 0.5f);
  const vec3 ambient = mix(frame.skyGround.rgb, upperSky, n.y * 0.5f + 0.5f);
  return albedo * (direct + ambient);
}

#endif
