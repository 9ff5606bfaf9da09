// The terrain's vertex stage, in the variants its defines select:
//   TERRAIN_HAZED          the aerial perspective read once per vertex and interpolated (a scene
//                          with an atmosphere): the haze varies smoothly over a terrain triangle
//                          (tens of metres across), and a 3D lookup per fragment costs about as
//                          much as the rest of the terrain pass on a CPU rasteriser;
//   TERRAIN_CLOUD_SHADOWS  the cloud shadow map's cascade coordinates computed per vertex
//                          (they are affine in the position, so they interpolate exactly;
//                          computing them per fragment cost about 1 ms a frame at 640x360 on
//                          lavapipe), and the terrain's own shadow read from the map per vertex
//                          (a long shadow's edge is soft over hundreds of metres, wider than a
//                          triangle; read per fragment it cost 0.8 ms a frame).
// Positions are in world metres; the camera position is subtracted before projecting so
// precision stays where the viewer is. Reversed-Z depth.
#extension GL_GOOGLE_include_directive : require
#include "scene_constants.h"

layout(binding = 0, std140) uniform Frame { SceneFrame frame; };
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 0) out vec3 outRelative;  // position relative to the camera (m)
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outColor;

#ifdef TERRAIN_HAZED
#include "vkfx/aerial_perspective.glsl"
layout(binding = 1) uniform sampler3D aerialPerspective;
layout(location = 3) out vec4 outHaze;  // rgb in-scattered (kcd/m^2), a transmittance
#endif

#ifdef TERRAIN_CLOUD_SHADOWS
#define CLOUD_SHADOW_MAP_BINDING 2
#include "vkfx/cloud_shadow_sampled.glsl"
layout(binding = 3, std140) uniform CloudShadow { CloudShadowParameters cloudShadow; };
layout(location = 4) out vec4 outShadowUv01;  // cascades 0 and 1
layout(location = 5) out vec4 outShadowUv23;  // cascades 2 and 3
layout(location = 6) out float outTerrainLight;  // the sun the terrain lets through
#endif

void main() {
  const vec3 relative = inPosition - frame.cameraPosition.xyz;
  const vec4 clip = frame.viewProjection * vec4(relative, 1.0f);
  outRelative = relative;
  outNormal = inNormal;
  outColor = inColor;
#ifdef TERRAIN_HAZED
  // Off-screen vertices (and those behind the camera, which are near it and barely hazed) read
  // the volume's edge.
  const vec2 uv = clamp(clip.xy / max(clip.w, 1e-6f) * 0.5f + 0.5f, 0.0f, 1.0f);
  const vec4 haze =
      aerialPerspectiveAt(aerialPerspective, uv, length(relative), frame.fog.y, frame.fog.z);
  outHaze = vec4(haze.rgb * frame.sunAboveAir.rgb, haze.a);
#endif
#ifdef TERRAIN_CLOUD_SHADOWS
  CLOUD_SHADOW_COORDINATES(cloudShadow, relative, outShadowUv01, outShadowUv23);
  outTerrainLight = cloudShadowAt(cloudShadow.info, outShadowUv01, outShadowUv23,
                                  cloudShadow.info.z + relative.y, kCloudShadowTerrain)
                        .y;
#endif
  gl_Position = clip;
}
