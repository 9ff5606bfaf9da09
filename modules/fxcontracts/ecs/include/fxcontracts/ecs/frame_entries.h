#pragma once
// The per-frame values the project's effects hand each other inside an engine frame, as entries
// of the frame graph's blackboard (engine/render/blackboard.h). The engine knows none of them:
// they are the contract between the effects' engine adapters (modules/*/ecs) and a renderer
// that hosts them (the sample's), and each restates, for the engine, a contract of the effects'
// own (the shader headers beside the modules, named below).
//
// Each entry is put when the graph is built by the feature that makes its resource, with the
// handles and the values known then; the values that can change from frame to frame are
// written again by the publishing pass when it executes, and a reader reads them when it
// executes, after the publisher because it reads the entry's texture.
#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "engine/render/frame_graph.h"

namespace fxcontracts::ecs {

// The sky's radiance around the camera (kcd/m^2), equirectangular: u the azimuth from +X
// towards +Z, v = 0 at the zenith, 0.5 at the horizon. Kept in GENERAL (read it with
// Access::SampledReadGeneral). Published by a feature that draws the sky (the atmosphere).
struct SkyRadiance {
  engine::render::TextureHandle texture;
};

// The sky with its clouds in it (the same layout and units as SkyRadiance): the clouds' sky
// light, kept in GENERAL. Put before the scene by the clouds' feature when it makes one; its pass
// refreshes a part of it after the scene each frame, so a reader in the scene (a reflection)
// sees the sky as the frames before made it. Its texels hold a sky once a frame has made it:
// read it while the scene's CoveredSkyLight (engine/render/exposure.h) is there, which the
// feature publishes from completed frames' sky lights.
struct CoveredSkyRadiance {
  engine::render::TextureHandle texture;
};

// The haze between the camera and every distance (fxcontracts/aerial_perspective.glsl), its
// radiance per unit of the sun's illuminance, kept in GENERAL. Published by the atmosphere's
// feature, or by a renderer that hazes with a neutral volume of its own.
struct AerialPerspective {
  engine::render::TextureHandle volume;
  // Written by the publishing pass every frame:
  std::uint32_t slices = 0;  // the volume's depth in slices
  float rangeMetres = 0.0f;  // the distance of its last slice
  // What the haze is made of, for effects that weigh its Mie share (god rays,
  // fxcontracts/god_rays.h): the air's scattering at the ground (per metre) and its Mie asymmetry.
  glm::vec3 rayleighScatteringPerMetre{0.0f};
  glm::vec3 mieScatteringPerMetre{0.0f};
  float miePhaseG = 0.8f;
};

// Put by whoever builds the frame, before any pass is added, when something in it receives
// cloud shadows (its geometry, or a feature that reads<CloudShadow>()). Without it no map is
// made.
struct CloudShadowWanted {};

// The lookup parameters of a cloud shadow map (fxcontracts/cloud_shadow.h's CloudShadowParameters:
// 13 vec4s, std140), as a receiver copies them into its uniforms.
using CloudShadowParameterBlock = std::array<glm::vec4, 13>;

// The clouds' shadow for receivers lit by the sun (fxcontracts/cloud_shadow.h), kept in GENERAL.
// Published by the clouds' feature when it casts shadows and CloudShadowWanted is there.
struct CloudShadow {
  engine::render::TextureHandle map;
  // Written by the pass that makes the map, every frame: its parameters (all 0 when it failed:
  // no shadow rather than a stale one), and whether the map was remade whole (no cascade
  // carried over from the frame before: a camera cut, new settings, a sun that turned), so a
  // receiver that keeps what it read from the map across frames must read it again.
  CloudShadowParameterBlock parameters{};
  bool remadeWhole = true;
};

}  // namespace fxcontracts::ecs
