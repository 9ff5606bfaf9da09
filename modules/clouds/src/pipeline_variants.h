#pragma once
// Which pipeline variants a frame uses, as pure functions of the settings and the frame's
// temporal decisions. Context::prepare() creates every variant variantsFor() lists, and
// dispatch() looks up the one its frame needs: the same functions decide both, so a prepared
// Settings never meets a missing variant.
#include <utility>
#include <vector>

#include "cloud_types.h"
#include "clouds/clouds.h"
#include "kit.h"
#include "programs.h"

namespace clouds::detail {

// `shadowMapReads` (shader::kShadowMapReads*): what the march reads of this frame's cloud
// shadow map (made before it): the terrain's shadow on the clouds (FrameInputs::terrain), the
// clouds' own beyond the light cone (Settings::cloudShadowsOnClouds); each compiled in alone.
// `edgeRays`: the tiles' march (shader::kEdgeRaysFind, which lists the edge tiles when the settings
// have edge rays) or the edge rays' (kEdgeRaysMarch). `heroClouds`: the variant for this frame's
// hero clouds (shader::kHeroClouds*, heroCloudVariant()). `nearField`: the near field's pass
// (Settings::nearFieldMetres; it marches no edge rays). `skyLight`: the sky light's pass
// (Settings::skyLight; no edge rays either).
SpecializationKey marchKey(const Settings& settings, bool workCounters,
                           std::uint32_t shadowMapReads,
                           std::uint32_t edgeRays = shader::kEdgeRaysFind,
                           std::uint32_t heroClouds = shader::kHeroCloudsOff,
                           bool nearField = false, bool skyLight = false);
// `history`: kHistoryNone, kHistoryInPlace or kHistoryReprojected (cloud_types.h).
// `lightning`: write the glow with this frame's flashes too.
SpecializationKey reconstructKey(std::uint32_t history, bool lightning);
// `history`: last frame's resolved near field is usable.
SpecializationKey nearResolveKey(bool history);
// `hazed`: the host gave an aerial perspective this frame; `godRays`: add the god rays' light;
// `lightning`: the clouds glow with this frame's flashes; `depthOutput`: store the cloud depth
// output (writesCloudDepth()); `nearField`: lay the near field over the rest.
SpecializationKey upsampleKey(bool temporalUpsampling, std::uint32_t outputHistory, bool hazed,
                              bool godRays, bool lightning, bool depthOutput, bool nearField);
// Whether the module writes the cloud depth output: the host reads it (Settings::depthOutput),
// or the bolts' pass does (lightningBoltSegments > 0).
bool writesCloudDepth(const Settings& settings);
// The bolts' pass; `hazed`: the host gave an aerial perspective this frame.
SpecializationKey boltsKey(bool hazed);

// The god-ray occlusion; `nearField`: the frame has one (TemporalFrame::nearField).
SpecializationKey godRayOcclusionKey(bool nearField);
// The god-ray mask and light, `light` shader::kGodRaysMaskHaze or kGodRaysGlow.
SpecializationKey godRaysKey(std::uint32_t light);
// The shadow map's (its empty-space skipping follows Settings::emptySpaceSkipping); `heroClouds`:
// the variant for the hero clouds that cast into it (shader::kHeroClouds*).
SpecializationKey shadowMapKey(const Settings& settings,
                               std::uint32_t heroClouds = shader::kHeroCloudsOff);

// Every variant `settings` can select in some frame (with or without history, still or moving,
// with or without the host's aerial perspective or terrain; with hero cloud assets loaded,
// without hero clouds, with them as authored and with living ones).
std::vector<std::pair<Program, SpecializationKey>> variantsFor(const Settings& settings,
                                                               bool workCounters,
                                                               bool heroClouds = false);

}  // namespace clouds::detail
