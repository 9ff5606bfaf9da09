#include "scene/scene_description.h"

#include <glm/gtc/constants.hpp>

#include "engine/core/error.h"
#include "engine/core/json_reader.h"

namespace sample {
namespace {

using engine::JsonReader;

// Ranges as clouds::Settings documents them (validateSettings() holds the module to them).
clouds::ecs::CloudQualityKnobs readCloudKnobs(const JsonReader& r) {
  clouds::ecs::CloudQualityKnobs k;
  if (r.has("maxViewSteps")) k.maxViewSteps = std::uint32_t(r.integer("maxViewSteps", 1, 16384));
  if (r.has("viewStepMetres")) k.viewStepMetres = float(r.number("viewStepMetres", 0.5, 1e4));
  if (r.has("lightSteps")) k.lightSteps = std::uint32_t(r.integer("lightSteps", 0, 64));
  if (r.has("transmittanceCutoff"))
    k.transmittanceCutoff = float(r.number("transmittanceCutoff", 0.0, 0.5));
  r.finish();
  return k;
}

CameraDescription readCamera(const JsonReader& r) {
  CameraDescription c;
  c.position = r.vec3("position", -1e7, 1e7);
  if (c.position.y < 0.0 || c.position.y > 50000.0) {
    r.fail("position", "altitude (y) must be in [0, 50000] m");
  }
  c.yawDegrees = r.number("yawDegrees", -360.0, 360.0, c.yawDegrees);
  c.pitchDegrees = r.number("pitchDegrees", -89.0, 89.0, c.pitchDegrees);
  c.verticalFovDegrees = r.number("verticalFovDegrees", 10.0, 120.0, c.verticalFovDegrees);
  c.speedMetresPerSecond = r.number("speedMetresPerSecond", 0.0, 1000.0, c.speedMetresPerSecond);
  const std::string quality =
      r.choice("cloudQuality", {"low", "medium", "high", "ultra", "reference"}, "medium");
  clouds::parseQuality(quality, &c.cloudQuality);
  if (r.has("frameTargetMilliseconds")) {
    c.frameTargetMilliseconds = r.number("frameTargetMilliseconds", 0.0, 1e5);
  }
  if (r.has("cloudKnobs")) c.cloudKnobs = readCloudKnobs(r.object("cloudKnobs"));
  const std::string sky =
      r.choice("atmosphereQuality", {"low", "medium", "high", "reference"}, "medium");
  atmosphere::parseQuality(sky, &c.atmosphereQuality);
  r.finish();
  return c;
}

SunDescription readSun(const JsonReader& r) {
  SunDescription s;
  s.timeOfDayHours = r.number("timeOfDayHours", 0.0, 24.0, s.timeOfDayHours);
  s.hoursPerSecond = r.number("hoursPerSecond", 0.0, 10.0, s.hoursPerSecond);
  s.maxElevationDegrees = r.number("maxElevationDegrees", 5.0, 90.0, s.maxElevationDegrees);
  s.azimuthOffsetDegrees = r.number("azimuthOffsetDegrees", -360.0, 360.0, s.azimuthOffsetDegrees);
  s.illuminance = r.number("illuminance", 0.0, 1000.0, s.illuminance);
  r.finish();
  return s;
}

TerrainDescription readTerrain(const JsonReader& r, const std::filesystem::path& sceneDir) {
  TerrainDescription t;
  const std::string gltf = r.string("gltf");
  t.gltf = gltf == "default" ? std::filesystem::path("default") : r.existingFile("gltf", sceneDir);
  t.castsShadows = r.boolean("castsShadows", true);
  if (r.has("snowlineMetres")) t.snowlineMetres = r.number("snowlineMetres", -1000.0, 20000.0, 0.0);
  t.closeDetail = r.boolean("closeDetail", true);
  r.finish();
  return t;
}

clouds::HeroCloudLifecycle readHeroCloudLifecycle(const JsonReader& r) {
  clouds::HeroCloudLifecycle l;
  l.startSeconds = r.number("startSeconds", -1e9, 1e9, l.startSeconds);
  l.growSeconds = float(r.number("growSeconds", 0.1, 1e6, l.growSeconds));
  l.matureSeconds = float(r.number("matureSeconds", 0.0, 1e6, l.matureSeconds));
  l.dissipateSeconds = float(r.number("dissipateSeconds", 0.1, 1e6, l.dissipateSeconds));
  l.restSeconds = float(r.number("restSeconds", 0.0, 1e6, l.restSeconds));
  l.repeat = r.boolean("repeat", l.repeat);
  r.finish();
  return l;
}

HeroCloudDescription readHeroCloud(const JsonReader& r, const std::filesystem::path& sceneDir) {
  HeroCloudDescription h;
  const std::string asset = r.string("asset");
  for (const char* name : kShippedHeroClouds) {
    if (asset == name) h.shipped = asset;
  }
  if (h.shipped.empty()) {
    h.file = r.existingFile("asset", sceneDir);
    const std::string extension = h.file.extension().string();
    if (extension != ".nvdf" && extension != ".vdb") {
      r.fail("asset",
             "a shipped cloud (towering_cumulus, cumulonimbus, arch) or an .nvdf or "
             ".vdb file, got " +
                 asset);
    }
  }
  h.positionMetres = r.vec3("positionMetres", -1e7, 1e7);
  h.scale = r.number("scale", 0.01, 100.0, h.scale);
  h.yawDegrees = r.number("yawDegrees", -360.0, 360.0, h.yawDegrees);
  if (r.has("lifecycle")) h.lifecycle = readHeroCloudLifecycle(r.object("lifecycle"));
  r.finish();
  return h;
}

CloudDescription readClouds(const JsonReader& r, const std::filesystem::path& sceneDir) {
  CloudDescription c;
  clouds::Settings& s = c.settings;
  s.layerBottomMetres = float(r.number("layerBottomMetres", 0.0, 20000.0, s.layerBottomMetres));
  s.layerTopMetres = float(r.number("layerTopMetres", 0.0, 30000.0, s.layerTopMetres));
  s.coverage = float(r.number("coverage", 0.0, 1.0, s.coverage));
  s.cloudType = float(r.number("cloudType", 0.0, 1.0, s.cloudType));
  s.typeVariation = float(r.number("typeVariation", 0.0, 2.0, s.typeVariation));
  s.densityVariation = float(r.number("densityVariation", 0.0, 1.0, s.densityVariation));
  s.densityMultiplier = float(r.number("densityMultiplier", 0.0, 1e6, s.densityMultiplier));
  s.extinctionPerMetre = float(r.number("extinctionPerMetre", 0.0, 100.0, s.extinctionPerMetre));
  s.anvilBias = float(r.number("anvilBias", 0.0, 1.0, s.anvilBias));
  s.detailErosion = float(r.number("detailErosion", 0.0, 1.0, s.detailErosion));
  s.weatherTileMetres = float(r.number("weatherTileMetres", 1000.0, 1e7, s.weatherTileMetres));
  s.weatherEvolutionPerSecond =
      float(r.number("weatherEvolutionPerSecond", 0.0, 1.0, s.weatherEvolutionPerSecond));
  s.shapeTileMetres = float(r.number("shapeTileMetres", 100.0, 1e7, s.shapeTileMetres));
  s.detailTileMetres = float(r.number("detailTileMetres", 10.0, 1e6, s.detailTileMetres));
  if (r.has("wind")) {
    const JsonReader wind = r.object("wind");
    c.windDirectionDegrees = wind.number("directionDegrees", -360.0, 360.0, 0.0);
    const double direction = glm::radians(c.windDirectionDegrees);
    s.windDirection = glm::vec2(float(std::cos(direction)), float(-std::sin(direction)));
    s.windSpeedMetresPerSecond =
        float(wind.number("speedMetresPerSecond", 0.0, 500.0, s.windSpeedMetresPerSecond));
    s.skewMetres = float(wind.number("skewMetres", 0.0, 20000.0, s.skewMetres));
    s.windShearDegrees = float(wind.number("shearDegrees", -180.0, 180.0, s.windShearDegrees));
    wind.finish();
  }
  if (r.has("lighting")) {
    const JsonReader l = r.object("lighting");
    s.albedo = float(l.number("albedo", 0.0, 1.0, s.albedo));
    s.phaseForwardG = float(l.number("phaseForwardG", -1.0, 1.0, s.phaseForwardG));
    s.phaseBackwardG = float(l.number("phaseBackwardG", -1.0, 1.0, s.phaseBackwardG));
    s.phaseBackwardWeight = float(l.number("phaseBackwardWeight", 0.0, 1.0, s.phaseBackwardWeight));
    s.silverIntensity = float(l.number("silverIntensity", 0.0, 10.0, s.silverIntensity));
    s.silverSpread = float(l.number("silverSpread", 0.0, 0.99, s.silverSpread));
    s.inScatterStrength = float(l.number("inScatterStrength", 0.0, 1.0, s.inScatterStrength));
    s.inScatterCoreProfile =
        float(l.number("inScatterCoreProfile", 0.01, 1.0, s.inScatterCoreProfile));
    s.ambientOcclusionStrength =
        float(l.number("ambientOcclusionStrength", 0.0, 1.0, s.ambientOcclusionStrength));
    s.ambientStrength = float(l.number("ambientStrength", 0.0, 100.0, s.ambientStrength));
    s.sunStrength = float(l.number("sunStrength", 0.0, 100.0, s.sunStrength));
    l.finish();
  }
  // Whether the layer casts shadows (its shadow map): off, no shadow pass, map or pipeline.
  if (!r.boolean("shadows", true)) s.shadowCascades = 0;
  // Whether the layer makes god rays (its mask, and the composite's shafts in the haze): off,
  // no pass, mask or pipeline. The quality preset picks the samples.
  if (r.boolean("godRays", false)) s.godRaySamples = kSceneGodRaySamples;
  // Whether the world's ambient and exposure meter see the sky with the layer in it (the sky
  // light, with an atmosphere's sky): off, no pass, map or pipeline, and the clear sky lights.
  s.skyLight = r.boolean("skyLight", true);
  c.noiseSeed = static_cast<std::uint32_t>(r.integer("noiseSeed", 0, 0xffffffffLL, c.noiseSeed));
  if (r.has("weatherMap")) c.weatherMap = r.existingFile("weatherMap", sceneDir);
  if (r.has("heroClouds")) {
    for (const JsonReader& hero : r.objects("heroClouds")) {
      c.heroClouds.push_back(readHeroCloud(hero, sceneDir));
    }
    if (c.heroClouds.size() > 64) r.fail("heroClouds", "at most 64 hero clouds");
  }
  // Whether the hero clouds carry their half-metre detail or show their voxels smooth.
  s.heroDetail = r.choice("heroDetail", {"uprezzed", "off"}, "uprezzed") == "off"
                     ? clouds::HeroDetail::Off
                     : clouds::HeroDetail::Uprezzed;
  r.finish();
  // Cross-field rules (layer top above bottom, ...) are the module's; report them here too.
  if (const std::string problem = clouds::validateSettings(s); !problem.empty()) {
    throw engine::Error(r.file() + ": clouds: " + problem);
  }
  return c;
}

glm::vec3 coefficients(const JsonReader& r, const std::string& key, const glm::vec3& fallback) {
  return glm::vec3(r.vec3(key, 0.0, 1e-3, glm::dvec3(fallback)));
}

AtmosphereDescription readAtmosphere(const JsonReader& r) {
  AtmosphereDescription a;
  atmosphere::Parameters& p = a.parameters;
  if (r.choice("preset", {"earth", "hazy"}, "earth") == "hazy") {
    // Continental haze: four times Earth's clear-day aerosols, a thicker aerosol layer.
    p.mieScatteringPerMetre *= 4.0f;
    p.mieExtinctionPerMetre *= 4.0f;
    p.mieScaleHeightMetres = 1800.0f;
  }
  p.rayleighScatteringPerMetre =
      coefficients(r, "rayleighScatteringPerMetre", p.rayleighScatteringPerMetre);
  p.rayleighScaleHeightMetres =
      float(r.number("rayleighScaleHeightMetres", 10.0, 1e6, p.rayleighScaleHeightMetres));
  p.mieScatteringPerMetre = coefficients(r, "mieScatteringPerMetre", p.mieScatteringPerMetre);
  p.mieExtinctionPerMetre = coefficients(r, "mieExtinctionPerMetre", p.mieExtinctionPerMetre);
  p.mieScaleHeightMetres =
      float(r.number("mieScaleHeightMetres", 10.0, 1e6, p.mieScaleHeightMetres));
  p.miePhaseG = float(r.number("miePhaseG", -0.99, 0.99, p.miePhaseG));
  p.ozoneAbsorptionPerMetre = coefficients(r, "ozoneAbsorptionPerMetre", p.ozoneAbsorptionPerMetre);
  a.groundAlbedoGiven = r.has("groundAlbedo");
  p.groundAlbedo = glm::vec3(r.vec3("groundAlbedo", 0.0, 1.0, glm::dvec3(p.groundAlbedo)));
  r.finish();
  // Cross-field rules (extinction at least scattering) are the module's; report them here too.
  if (const std::string problem = atmosphere::validateParameters(p); !problem.empty()) {
    throw engine::Error(r.file() + ": atmosphere: " + problem);
  }
  return a;
}

FogDescription readFog(const JsonReader& r) {
  FogDescription f;
  f.densityPerMetre = r.number("densityPerMetre", 0.0, 0.01);
  r.finish();
  return f;
}

WaterDescription readWater(const JsonReader& r) {
  WaterDescription w;
  w.levelMetres = r.number("levelMetres", -1000.0, 10000.0);
  w.colour = r.vec3("colour", 0.0, 1.0, w.colour);
  w.clarity = r.number("clarity", 0.0, 1.0, w.clarity);
  r.finish();
  return w;
}

ExposureDescription readExposure(const JsonReader& r) {
  ExposureDescription e;
  e.automatic = r.choice("mode", {"auto", "manual"}, "auto") == "auto";
  e.ev100 = r.number("ev100", -10.0, 25.0, e.ev100);
  e.compensationEv = r.number("compensationEv", -10.0, 10.0, e.compensationEv);
  e.adaptationSeconds = r.number("adaptationSeconds", 0.0, 60.0, e.adaptationSeconds);
  r.finish();
  return e;
}

// A storm in `clouds`: its cells given, or found where the clouds' weather holds the most
// cumulonimbus around the camera.
// With changing weather the storm strikes at its states' rates, and its cells are found under
// the states that strike most (the regions' too).
LightningDescription readLightning(const JsonReader& r, const CloudDescription& clouds,
                                   const std::optional<WeatherDescription>& weather,
                                   const CameraDescription& camera) {
  LightningDescription l;
  clouds::ecs::LightningStorm& s = l.storm;
  if (r.has("cells") == r.has("cellsFromWeather")) {
    r.fail("cells", "a storm needs either cells or cellsFromWeather");
  }
  if (r.has("cells")) {
    for (const JsonReader& cell : r.objects("cells")) {
      clouds::ecs::LightningCell c;
      c.positionMetres = cell.vec3("position", -1e7, 1e7);
      c.radiusMetres = float(cell.number("radiusMetres", 10.0, 1e5, c.radiusMetres));
      cell.finish();
      s.cells.push_back(c);
    }
    if (s.cells.empty()) r.fail("cells", "a storm needs at least one cell");
  } else {
    const JsonReader found = r.object("cellsFromWeather");
    const auto count = static_cast<std::uint32_t>(found.integer("count", 1, 16, 3));
    const double within = found.number("withinMetres", 1000.0, 1e6, 20000.0);
    const auto radius = float(found.number("radiusMetres", 10.0, 1e5, 4000.0));
    found.finish();
    if (clouds.weatherMap ||
        (weather && !scheduledWeatherMaps(weather->schedule, clouds.weatherMap).empty())) {
      r.fail("cellsFromWeather", "found in the procedural weather only, not a painted map");
    }
    const glm::dvec2 centre(camera.position.x, camera.position.z);
    const clouds::Settings stormy =
        weather ? clouds::withWeather(clouds.settings, weather->schedule.stormiest())
                : clouds.settings;
    const std::vector<clouds::WeatherRegion> regions =
        weather ? weather->stormiestRegions() : std::vector<clouds::WeatherRegion>{};
    s.cells = clouds::ecs::stormCellsFromWeather(stormy, clouds.noiseSeed, centre, within, count,
                                                 radius, regions);
    if (s.cells.empty()) {
      r.fail("cellsFromWeather",
             "no cumulonimbus within " + std::to_string(within) +
                 " m of the camera (type >= 0.75, coverage >= 0.5): raise cloudType or coverage");
    }
  }
  if (weather && r.has("strikesPerMinute")) {
    r.fail("strikesPerMinute", "the weather's states set the rate (lightningStrikesPerMinute)");
  }
  s.strikesPerMinute = r.number("strikesPerMinute", 0.0, 600.0, s.strikesPerMinute);
  s.seed = static_cast<std::uint32_t>(r.integer("seed", 0, 0xffffffffLL, s.seed));
  s.groundFraction = r.number("groundFraction", 0.0, 1.0, s.groundFraction);
  s.radiance = float(r.number("radiance", 0.0, 1e6, s.radiance));
  s.groundAltitudeMetres =
      r.number("groundAltitudeMetres", -1000.0, 10000.0, s.groundAltitudeMetres);
  r.finish();
  return l;
}

}  // namespace

SceneDescription loadSceneDescription(const std::filesystem::path& file) {
  const nlohmann::json json = JsonReader::parseFile(file);
  const JsonReader root(json, file.string());
  const std::filesystem::path dir = file.parent_path();
  SceneDescription scene;
  scene.file = file;
  scene.name = root.string("name");
  scene.camera = readCamera(root.object("camera"));
  if (root.has("sun")) scene.sun = readSun(root.object("sun"));
  if (root.has("terrain")) scene.terrain = readTerrain(root.object("terrain"), dir);
  if (root.has("clouds")) scene.clouds = readClouds(root.object("clouds"), dir);
  if (root.has("weather")) {
    if (!scene.clouds) root.fail("weather", "weather is the clouds': the scene has none");
    scene.weather = readWeather(root.object("weather"), scene.clouds->settings,
                                scene.clouds->windDirectionDegrees, scene.clouds->weatherMap, dir);
    if (scene.weather->strikes() && !root.has("lightning")) {
      root.fail("weather", "a state strikes lightning: the scene needs a \"lightning\" storm");
    }
  }
  if (root.has("lightning")) {
    if (!scene.clouds) root.fail("lightning", "lightning glows in clouds: the scene has none");
    scene.lightning =
        readLightning(root.object("lightning"), *scene.clouds, scene.weather, scene.camera);
  }
  if (root.has("atmosphere")) scene.atmosphere = readAtmosphere(root.object("atmosphere"));
  if (root.has("fog")) scene.fog = readFog(root.object("fog"));
  if (scene.atmosphere && scene.fog) {
    root.fail("fog", "a scene has an atmosphere or fog, not both (the atmosphere hazes itself)");
  }
  if (root.has("water")) scene.water = readWater(root.object("water"));
  if (root.has("exposure")) scene.exposure = readExposure(root.object("exposure"));
  root.finish();
  return scene;
}

}  // namespace sample
