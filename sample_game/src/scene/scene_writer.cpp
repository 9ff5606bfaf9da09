#include "scene/scene_writer.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/core/error.h"

namespace sample {
namespace {

using nlohmann::json;

json vec3(const glm::dvec3& v) {
  return json::array({v.x, v.y, v.z});
}
json vec3(const glm::vec3& v) {
  return json::array({double(v.x), double(v.y), double(v.z)});
}

std::string lowercase(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return name;
}

std::string absolutePath(const std::filesystem::path& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

json cameraJson(const CameraDescription& c) {
  json j = {{"position", vec3(c.position)},
            {"yawDegrees", c.yawDegrees},
            {"pitchDegrees", c.pitchDegrees},
            {"verticalFovDegrees", c.verticalFovDegrees},
            {"speedMetresPerSecond", c.speedMetresPerSecond},
            {"cloudQuality", lowercase(clouds::qualityName(c.cloudQuality))},
            {"atmosphereQuality", lowercase(atmosphere::qualityName(c.atmosphereQuality))}};
  if (c.frameTargetMilliseconds) j["frameTargetMilliseconds"] = *c.frameTargetMilliseconds;
  const clouds::ecs::CloudQualityKnobs& k = c.cloudKnobs;
  if (k.any()) {
    json knobs = json::object();
    if (k.maxViewSteps) knobs["maxViewSteps"] = *k.maxViewSteps;
    if (k.viewStepMetres) knobs["viewStepMetres"] = double(*k.viewStepMetres);
    if (k.lightSteps) knobs["lightSteps"] = *k.lightSteps;
    if (k.transmittanceCutoff) knobs["transmittanceCutoff"] = double(*k.transmittanceCutoff);
    j["cloudKnobs"] = knobs;
  }
  return j;
}

json sunJson(const SunDescription& s) {
  return {{"timeOfDayHours", s.timeOfDayHours},
          {"hoursPerSecond", s.hoursPerSecond},
          {"maxElevationDegrees", s.maxElevationDegrees},
          {"azimuthOffsetDegrees", s.azimuthOffsetDegrees},
          {"illuminance", s.illuminance}};
}

json terrainJson(const TerrainDescription& t) {
  json j = {{"gltf", t.gltf == "default" ? std::string("default") : absolutePath(t.gltf)},
            {"castsShadows", t.castsShadows},
            {"closeDetail", t.closeDetail}};
  if (t.snowlineMetres) j["snowlineMetres"] = *t.snowlineMetres;
  return j;
}

json heroCloudJson(const HeroCloudDescription& h) {
  json j = {{"asset", h.shipped.empty() ? absolutePath(h.file) : h.shipped},
            {"positionMetres", vec3(h.positionMetres)},
            {"scale", h.scale},
            {"yawDegrees", h.yawDegrees}};
  if (h.lifecycle) {
    const clouds::HeroCloudLifecycle& l = *h.lifecycle;
    j["lifecycle"] = {{"startSeconds", l.startSeconds},
                      {"growSeconds", double(l.growSeconds)},
                      {"matureSeconds", double(l.matureSeconds)},
                      {"dissipateSeconds", double(l.dissipateSeconds)},
                      {"restSeconds", double(l.restSeconds)},
                      {"repeat", l.repeat}};
  }
  return j;
}

json cloudsJson(const CloudDescription& c) {
  const clouds::Settings& s = c.settings;
  json j = {{"layerBottomMetres", double(s.layerBottomMetres)},
            {"layerTopMetres", double(s.layerTopMetres)},
            {"coverage", double(s.coverage)},
            {"cloudType", double(s.cloudType)},
            {"typeVariation", double(s.typeVariation)},
            {"densityVariation", double(s.densityVariation)},
            {"densityMultiplier", double(s.densityMultiplier)},
            {"extinctionPerMetre", double(s.extinctionPerMetre)},
            {"anvilBias", double(s.anvilBias)},
            {"detailErosion", double(s.detailErosion)},
            {"weatherTileMetres", double(s.weatherTileMetres)},
            {"weatherEvolutionPerSecond", double(s.weatherEvolutionPerSecond)},
            {"shapeTileMetres", double(s.shapeTileMetres)},
            {"detailTileMetres", double(s.detailTileMetres)},
            {"wind",
             {{"directionDegrees", c.windDirectionDegrees},
              {"speedMetresPerSecond", double(s.windSpeedMetresPerSecond)},
              {"skewMetres", double(s.skewMetres)},
              {"shearDegrees", double(s.windShearDegrees)}}},
            {"lighting",
             {{"albedo", double(s.albedo)},
              {"phaseForwardG", double(s.phaseForwardG)},
              {"phaseBackwardG", double(s.phaseBackwardG)},
              {"phaseBackwardWeight", double(s.phaseBackwardWeight)},
              {"silverIntensity", double(s.silverIntensity)},
              {"silverSpread", double(s.silverSpread)},
              {"inScatterStrength", double(s.inScatterStrength)},
              {"inScatterCoreProfile", double(s.inScatterCoreProfile)},
              {"ambientOcclusionStrength", double(s.ambientOcclusionStrength)},
              {"ambientStrength", double(s.ambientStrength)},
              {"sunStrength", double(s.sunStrength)}}},
            {"shadows", s.shadowCascades > 0},
            {"godRays", s.godRaySamples > 0},
            {"skyLight", s.skyLight},
            {"noiseSeed", c.noiseSeed},
            {"heroDetail", s.heroDetail == clouds::HeroDetail::Off ? "off" : "uprezzed"}};
  if (c.weatherMap) j["weatherMap"] = absolutePath(*c.weatherMap);
  if (!c.heroClouds.empty()) {
    json heroes = json::array();
    for (const HeroCloudDescription& h : c.heroClouds) heroes.push_back(heroCloudJson(h));
    j["heroClouds"] = heroes;
  }
  return j;
}

// With changing weather the states set the rate: the storm does not say one.
json lightningJson(const LightningDescription& l, bool weather) {
  const clouds::ecs::LightningStorm& s = l.storm;
  json cells = json::array();
  for (const clouds::ecs::LightningCell& cell : s.cells) {
    cells.push_back(
        {{"position", vec3(cell.positionMetres)}, {"radiusMetres", double(cell.radiusMetres)}});
  }
  json j = {{"cells", cells},
            {"seed", s.seed},
            {"groundFraction", s.groundFraction},
            {"radiance", double(s.radiance)},
            {"groundAltitudeMetres", s.groundAltitudeMetres}};
  if (!weather) j["strikesPerMinute"] = s.strikesPerMinute;
  return j;
}

json atmosphereJson(const AtmosphereDescription& a) {
  const atmosphere::Parameters& p = a.parameters;
  json j = {{"preset", "earth"},
            {"rayleighScatteringPerMetre", vec3(p.rayleighScatteringPerMetre)},
            {"rayleighScaleHeightMetres", double(p.rayleighScaleHeightMetres)},
            {"mieScatteringPerMetre", vec3(p.mieScatteringPerMetre)},
            {"mieExtinctionPerMetre", vec3(p.mieExtinctionPerMetre)},
            {"mieScaleHeightMetres", double(p.mieScaleHeightMetres)},
            {"miePhaseG", double(p.miePhaseG)},
            {"ozoneAbsorptionPerMetre", vec3(p.ozoneAbsorptionPerMetre)}};
  if (a.groundAlbedoGiven) j["groundAlbedo"] = vec3(p.groundAlbedo);
  return j;
}

json exposureJson(const ExposureDescription& e) {
  return {{"mode", e.automatic ? "auto" : "manual"},
          {"ev100", e.ev100},
          {"compensationEv", e.compensationEv},
          {"adaptationSeconds", e.adaptationSeconds}};
}

}  // namespace

std::string sceneJson(const SceneDescription& scene) {
  json j = {
      {"name", scene.name}, {"camera", cameraJson(scene.camera)}, {"sun", sunJson(scene.sun)}};
  if (scene.terrain) j["terrain"] = terrainJson(*scene.terrain);
  if (scene.clouds) j["clouds"] = cloudsJson(*scene.clouds);
  if (scene.weather) j["weather"] = weatherJson(*scene.weather);
  if (scene.lightning) j["lightning"] = lightningJson(*scene.lightning, scene.weather.has_value());
  if (scene.atmosphere) j["atmosphere"] = atmosphereJson(*scene.atmosphere);
  if (scene.fog) j["fog"] = {{"densityPerMetre", scene.fog->densityPerMetre}};
  if (scene.water) {
    const glm::dvec3& c = scene.water->colour;
    j["water"] = {{"levelMetres", scene.water->levelMetres},
                  {"colour", {c.r, c.g, c.b}},
                  {"clarity", scene.water->clarity}};
  }
  j["exposure"] = exposureJson(scene.exposure);
  return j.dump(2) + "\n";
}

void writeSceneFile(const SceneDescription& scene, const std::filesystem::path& file) {
  std::ofstream out(file);
  out << sceneJson(scene);
  if (!out) throw engine::Error(file.string() + ": cannot write the scene");
}

}  // namespace sample
