#include "programs.h"

#include <span>
#include <vector>

#include "cloud_types.h"
#include "clouds_shaders/cloud_march.comp.spv.h"
#include "clouds_shaders/cloud_shadow_map.comp.spv.h"
#include "clouds_shaders/composite.comp.spv.h"
#include "clouds_shaders/depth_downsample.comp.spv.h"
#include "clouds_shaders/god_ray_occlusion.comp.spv.h"
#include "clouds_shaders/god_rays.comp.spv.h"
#include "clouds_shaders/hero_light_volume.comp.spv.h"
#include "clouds_shaders/hero_noise.comp.spv.h"
#include "clouds_shaders/hero_noise_mip.comp.spv.h"
#include "clouds_shaders/lightning_bolts.comp.spv.h"
#include "clouds_shaders/near_field_resolve.comp.spv.h"
#include "clouds_shaders/noise_curl.comp.spv.h"
#include "clouds_shaders/noise_detail.comp.spv.h"
#include "clouds_shaders/noise_mip.comp.spv.h"
#include "clouds_shaders/noise_shape.comp.spv.h"
#include "clouds_shaders/reconstruct.comp.spv.h"
#include "clouds_shaders/sky_ambient.comp.spv.h"
#include "clouds_shaders/sky_light.comp.spv.h"
#include "clouds_shaders/terrain_shadow_map.comp.spv.h"
#include "clouds_shaders/upsample.comp.spv.h"
#include "clouds_shaders/weather_max.comp.spv.h"
#include "clouds_shaders/weather_procedural.comp.spv.h"
#include "clouds_shaders/weather_resample.comp.spv.h"

namespace clouds::detail {
namespace {

using namespace shader;
constexpr VkDescriptorType kImage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkDescriptorType kTexture = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkDescriptorType kUniforms = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;  // frame_uniforms.glsl
constexpr VkDescriptorType kBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;

struct ProgramDesc {
  Program program;
  std::span<const std::uint32_t> spirv;
  std::vector<Binding> bindings;
  std::uint32_t pushConstantBytes;
  const char* name;
};

std::vector<ProgramDesc> programTable() {
  return {
      {Program::ShapeNoise,
       noise_shape_comp_spv,
       {{kGeneratorTarget, kImage}},
       sizeof(NoiseConstants),
       "shape noise generator"},
      {Program::DetailNoise,
       noise_detail_comp_spv,
       {{kGeneratorTarget, kImage}},
       sizeof(NoiseConstants),
       "detail noise generator"},
      {Program::CurlNoise,
       noise_curl_comp_spv,
       {{kGeneratorTarget, kImage}},
       sizeof(NoiseConstants),
       "curl noise generator"},
      {Program::NoiseMip,
       noise_mip_comp_spv,
       {{kGeneratorTarget, kImage}},
       sizeof(NoiseMipConstants),
       "noise mip chain"},
      {Program::Weather,
       weather_procedural_comp_spv,
       {{kGeneratorTarget, kImage}},
       sizeof(WeatherConstants),
       "weather generator"},
      {Program::WeatherResample,
       weather_resample_comp_spv,
       {{kResampleTarget, kImage}, {kResampleSource, kTexture}, {kResampleBlendSource, kTexture}},
       sizeof(ResampleConstants),
       "weather resample"},
      {Program::WeatherMaxima,
       weather_max_comp_spv,
       {{kMaximaSource, kImage}, {kMaximaTarget, kImage}},
       sizeof(MaximaConstants),
       "weather maxima"},
      {Program::SkyAmbient,
       sky_ambient_comp_spv,
       {{kSkyAmbientUniforms, kBuffer},
        {kSkyAmbientSky, kTexture},
        {kSkyAmbientShadowMap, kTexture},
        {kSkyAmbientLastSkyLight, kBuffer}},
       sizeof(AmbientConstants),
       "sky ambient"},
      {Program::SkyLight,
       sky_light_comp_spv,
       {{kBindingUniforms, kUniforms},
        {kSkyLightHostSky, kTexture},
        {kSkyLightClouds, kImage},
        {kSkyLightShadowMap, kTexture},
        {kSkyLightMap, kImage},
        {kSkyLightMeasures, kBuffer},
        {kSkyLightShadowParameters, kUniforms}},
       sizeof(SkyLightConstants),
       "sky light"},
      {Program::SceneDistance,
       depth_downsample_comp_spv,
       {{kBindingUniforms, kUniforms},
        {kSceneDistanceHostDepth, kTexture},
        {kSceneDistanceOut, kImage}},
       sizeof(FrameUniformsIndex),
       "scene distance"},
      {Program::March,
       cloud_march_comp_spv,
       {{kBindingUniforms, kUniforms},    {kMarchShapeNoise, kImage},
        {kMarchDetailNoise, kImage},      {kMarchWeatherMap, kImage},
        {kMarchCurlNoise, kImage},        {kMarchSceneDistance, kImage},
        {kMarchSamplesOut, kImage},       {kMarchWeatherMaxFine, kImage},
        {kMarchWeatherMaxCoarse, kImage}, {kMarchCounters, kBuffer},
        {kMarchCloudShadow, kTexture},    {kMarchCloudShadowParameters, kUniforms},
        {kMarchTraceHistory, kImage},     {kMarchEdgeRayList, kBuffer},
        {kMarchHeroAtlas, kImage},        {kMarchHeroClouds, kUniforms},
        {kMarchHeroLight, kImage},        {kMarchHeroNoise, kImage},
        {kMarchNearFieldOut, kImage},     {kMarchSkyLightOut, kImage}},
       sizeof(FrameUniformsIndex),
       "march"},
      {Program::HeroLight,
       hero_light_volume_comp_spv,
       {{kLightSweepAtlas, kImage},
        {kLightSweepClouds, kUniforms},
        {kLightSweepVolume, kImage},
        {kLightSweepNoise, kImage}},
       sizeof(HeroLightConstants),
       "hero light volume"},
      {Program::HeroNoise,
       hero_noise_comp_spv,
       {{kGeneratorTarget, kImage}},
       sizeof(NoiseConstants),
       "hero detail noise generator"},
      {Program::HeroNoiseMip,
       hero_noise_mip_comp_spv,
       {{kGeneratorTarget, kImage}},
       sizeof(NoiseMipConstants),
       "hero detail noise mip chain"},
      {Program::Reconstruct,
       reconstruct_comp_spv,
       {{kBindingUniforms, kUniforms},
        {kReconstructFresh, kImage},
        {kReconstructHistory, kImage},
        {kReconstructOut, kImage},
        {kReconstructFlashes, kUniforms},
        {kReconstructGlow, kImage},
        {kReconstructSceneDistance, kImage}},
       sizeof(FrameUniformsIndex),
       "reconstruct"},
      {Program::NearResolve,
       near_field_resolve_comp_spv,
       {{kBindingUniforms, kUniforms},
        {kNearResolveFresh, kImage},
        {kNearResolveHistory, kImage},
        {kNearResolveOut, kImage}},
       sizeof(FrameUniformsIndex),
       "near field resolve"},
      {Program::Upsample,
       upsample_comp_spv,
       {{kBindingUniforms, kUniforms},
        {kUpsampleTraceSamples, kImage},
        {kUpsampleHostDepth, kTexture},
        {kUpsampleRadianceOut, kImage},
        {kUpsampleDepthOut, kImage},
        {kUpsampleFresh, kImage},
        {kUpsampleHistory, kImage},
        {kUpsampleHistoryOut, kImage},
        {kUpsampleAerialPerspective, kTexture},
        {kUpsampleGodRayLight, kTexture},
        {kUpsampleLightningGlow, kTexture},
        {kUpsampleNearField, kImage}},
       sizeof(FrameUniformsIndex),
       "upsample"},
      {Program::ShadowMap,
       cloud_shadow_map_comp_spv,
       {{kBindingUniforms, kUniforms},
        {kShadowShapeNoise, kImage},
        {kShadowWeatherMap, kImage},
        {kShadowWeatherMaxFine, kImage},
        {kShadowWeatherMaxCoarse, kImage},
        {kShadowMapOut, kImage},
        {kShadowMapSpare, kImage},
        {kShadowHeroAtlas, kImage},
        {kShadowHeroClouds, kUniforms},
        {kShadowHeroNoise, kImage}},
       sizeof(ShadowMapConstants),
       "shadow map"},
      {Program::TerrainShadow,
       terrain_shadow_map_comp_spv,
       {{kTerrainShadowHeight, kTexture}, {kTerrainShadowMap, kImage}},
       sizeof(TerrainShadowConstants),
       "terrain shadow"},
      {Program::Composite,
       composite_comp_spv,
       {{kCompositeHostColor, kImage}, {kCompositeClouds, kImage}},
       sizeof(CompositeConstants),
       "composite"},
      {Program::GodRayOcclusion,
       god_ray_occlusion_comp_spv,
       {{kBindingUniforms, kUniforms},
        {kGodRayTraceSamples, kImage},
        {kGodRaySceneDistance, kImage},
        {kGodRayOcclusionOut, kImage},
        {kGodRayNearField, kImage}},
       sizeof(GodRayOcclusionConstants),
       "god-ray occlusion"},
      {Program::GodRays,
       god_rays_comp_spv,
       {{kGodRayOcclusion, kTexture},
        {kGodRayMaskOut, kImage},
        {kGodRayHaze, kTexture},
        {kGodRayUniforms, kUniforms},
        {kGodRayLightOut, kImage}},
       sizeof(GodRayParameters),
       "god rays"},
      {Program::LightningBolts,
       lightning_bolts_comp_spv,
       {{kBindingUniforms, kUniforms},
        {kBoltsHostDepth, kTexture},
        {kBoltsRadiance, kImage},
        {kBoltsDepth, kImage},
        {kBoltsAerialPerspective, kTexture},
        {kBoltsPieces, kBuffer}},
       sizeof(LightningBoltsConstants),
       "lightning bolts"},
  };
}

}  // namespace

Programs::Programs(const DeviceContext& device, bool composite) {
  for (const ProgramDesc& desc : programTable()) {
    if (desc.program == Program::Composite && !composite) continue;
    auto& program = programs_[index(desc.program)];
    program = std::make_unique<ComputeProgram>(device, desc.spirv, desc.bindings,
                                               desc.pushConstantBytes, desc.name);
    // Programs without specialization constants have one variant: made now (the shadow map's,
    // the god rays' and the hero clouds' light volume and detail noise by prepare(), only for
    // settings and assets that have them).
    const bool specialised =
        desc.program == Program::March || desc.program == Program::Reconstruct ||
        desc.program == Program::Upsample || desc.program == Program::ShadowMap ||
        desc.program == Program::TerrainShadow || desc.program == Program::GodRayOcclusion ||
        desc.program == Program::GodRays || desc.program == Program::LightningBolts ||
        desc.program == Program::HeroLight || desc.program == Program::HeroNoise ||
        desc.program == Program::HeroNoiseMip;
    if (!specialised) program->prepare();
  }
}

}  // namespace clouds::detail
