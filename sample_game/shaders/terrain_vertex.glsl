// The terrain's vertex stage. With TERRAIN_HAZED (a scene with an atmosphere) it reads the
// aerial perspective once per vertex, interpolated: the haze varies smoothly over a terrain
// triangle (tens of metres across), and a 3D lookup per fragment costs about as much as the
// rest of the terrain pass on a CPU rasteriser. (The sun's share through the clouds and past
// the terrain, TERRAIN_CLOUD_SHADOWS, is the fragment stage's: terrain_sunlight_map.h.)
// In a storm's lightning variant (kLightning) it also gives the brightest flash in progress's
// falloff and direction per vertex: they change over hundreds of metres (the glowing core is a
// sixth of the flash's reach across), far more slowly than the mesh's triangles; the fragment
// stage only turns them to its detailed normal (all of it per fragment cost the scene pass about
// 0.3 ms at 640x360 on lavapipe). Positions are in world metres; the camera position is
// subtracted before projecting so precision stays where the viewer is. Reversed-Z depth.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "scene_constants.h"
#include "fxcontracts/lightning_light.h"

layout(binding = kTerrainFrameBinding, std140) uniform Frame { SceneFrame frame; };
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 5) in vec2 inUv;
layout(location = 0) out vec3 outRelative;  // position relative to the camera (m)
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outColor;
layout(location = 5) out vec2 outUv;  // the base colour texture's
// The flash's light per unit of its radiance (0 without lightning): xyz the direct light's
// irradiance on a surface facing it (its direction times its size), w the sky light's.
layout(location = 4) out vec4 outFlashLight;
// A storm's scene: the brightest flash in progress lights the ground (none: no such code).
layout(constant_id = 0) const bool kLightning = false;

#ifdef TERRAIN_HAZED
#include "fxcontracts/aerial_perspective.glsl"
layout(binding = kTerrainHazeBinding) uniform sampler3D aerialPerspective;
layout(location = 3) out vec4 outHaze;  // rgb in-scattered (kcd/m^2), a transmittance
#endif

void main() {
  const vec3 relative = inPosition - frame.cameraPosition.xyz;
  const vec4 clip = frame.viewProjection * vec4(relative, 1.0f);
  outRelative = relative;
  outNormal = inNormal;
  outColor = inColor;
  outUv = inUv;
  // A lightning flash lights the ground (fxcontracts/lightning_light.h): directly, the glowing
  // core of the cloud around it as a sphere of its radiance, whose irradiance at distance d is
  // pi L (core / d)^2 (Lambert: albedo / pi of it); and from the whole sky, the cloud the core
  // lights (terrain_fragment.glsl weighs each by the surface's normal).
  outFlashLight = vec4(0.0f);
  if (kLightning) {
    const float core = flashCoreMetres(frame.flash.w);
    const vec3 toFlash = frame.flash.xyz - relative;
    const float distanceSquared = dot(toFlash, toFlash);
    const float d2 = max(distanceSquared, core * core);
    outFlashLight = vec4(toFlash * (core * core / d2 * inversesqrt(d2)),
                         flashSkyLightSquared(distanceSquared, frame.flash.w));
  }
#ifdef TERRAIN_HAZED
  // Off-screen vertices (and those behind the camera, which are near it and barely hazed) read
  // the volume's edge.
  const vec2 uv = clamp(clip.xy / max(clip.w, 1e-6f) * 0.5f + 0.5f, 0.0f, 1.0f);
  const vec4 haze =
      aerialPerspectiveAt(aerialPerspective, uv, length(relative), frame.fog.y, frame.fog.z);
  outHaze = vec4(haze.rgb * frame.sunAboveAir.rgb, haze.a);
#endif
  gl_Position = clip;
}
