#include "clouds/ecs/cloud_frame.h"

#include <algorithm>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/lightning.h"
#include "clouds/hero_cloud_life.h"
#include "engine/ecs/frame_time.h"
#include "engine/render/scene_components.h"

namespace clouds::ecs {

using namespace engine;

namespace {

double clockSeconds(engine::ecs::World& world) {
  const auto* time = world.ctx().tryGet<engine::ecs::FrameTime>();
  return time ? time->elapsedSeconds : 0.0;
}

// The layer's settings under the weather now, with room for a storm's flashes (and so the
// glow's code) and the weather's regions.
clouds::Settings layerSettings(engine::ecs::World& world) {
  clouds::Settings settings;
  world.view<const CloudLayer>().each([&](const CloudLayer& layer) { settings = layer.settings; });
  if (const std::optional<clouds::WeatherState> weather = currentWeather(world)) {
    settings = clouds::withWeather(settings, *weather);
  }
  world.view<const LightningStorm>().each([&](const LightningStorm&) {
    settings.lightningFlashes = kLightningFlashes;
    settings.lightningBoltSegments = kLightningBoltSegments;
  });
  // Room for the weather's regions (and so their code) only in a scene that has some.
  world.view<const CloudLayer, const CloudWeather>().each(
      [&](const CloudLayer&, const CloudWeather& w) {
        settings.weatherRegions = static_cast<std::uint32_t>(w.regions.size());
        const bool storm = std::any_of(w.regions.begin(), w.regions.end(), [](const auto& r) {
          return r.place.vortex.eyeRadiusMetres > 0.0f;
        });
        settings.superstorms = storm ? 1u : 0u;
      });
  return settings;
}

}  // namespace

std::optional<clouds::WeatherState> currentWeather(engine::ecs::World& world) {
  std::optional<clouds::WeatherState> weather;
  const double now = clockSeconds(world);
  world.view<const CloudLayer, const CloudWeather>().each(
      [&](const CloudLayer&, const CloudWeather& w) { weather = w.timeline.stateAt(now); });
  return weather;
}

std::vector<clouds::WeatherRegion> currentWeatherRegions(engine::ecs::World& world) {
  std::vector<clouds::WeatherRegion> regions;
  const double now = clockSeconds(world);
  world.view<const CloudLayer, const CloudWeather>().each(
      [&](const CloudLayer&, const CloudWeather& w) { regions = w.regionsAt(now); });
  return regions;
}

std::optional<clouds::WeatherPhase> paintedWeatherPhase(engine::ecs::World& world) {
  std::optional<clouds::WeatherPhase> phase;
  const double now = clockSeconds(world);
  world.view<const CloudLayer, const CloudWeather>().each(
      [&](const CloudLayer&, const CloudWeather& w) {
        if (!w.keyWeatherMaps.empty()) phase = w.timeline.phaseAt(now);
      });
  return phase;
}

clouds::Settings CloudQualityKnobs::appliedTo(clouds::Settings settings) const {
  if (maxViewSteps) settings.maxViewSteps = *maxViewSteps;
  if (viewStepMetres) settings.viewStepMetres = *viewStepMetres;
  if (lightSteps) settings.lightSteps = *lightSteps;
  if (transmittanceCutoff) settings.transmittanceCutoff = *transmittanceCutoff;
  return settings;
}

clouds::Settings cloudSettings(engine::ecs::World& world) {
  const clouds::Settings layer = layerSettings(world);
  clouds::Settings settings = layer;
  world.view<const render::Camera>().each([&](engine::ecs::Entity entity, const render::Camera&) {
    if (const auto* quality = world.tryGet<const CloudQuality>(entity)) {
      settings = quality->knobs.appliedTo(clouds::settingsFor(quality->preset, layer));
    }
  });
  return settings;
}

clouds::Settings cloudSettingsFor(engine::ecs::World& world, clouds::Quality preset) {
  return clouds::settingsFor(preset, layerSettings(world));
}

std::vector<clouds::LightningFlash> lightningFlashes(engine::ecs::World& world,
                                                     std::uint32_t capacity) {
  std::vector<clouds::LightningFlash> flashes;
  const auto* active = world.ctx().tryGet<ActiveLightning>();
  if (active == nullptr || capacity == 0) return flashes;
  const double now = world.ctx().get<engine::ecs::FrameTime>().elapsedSeconds;
  for (const LightningStrike& strike : active->strikes) {
    const float brightness = strikeEnvelope(strike, now) * strike.energy;
    if (!(brightness > 0.0f)) continue;
    clouds::LightningFlash flash;
    flash.positionMetres = strike.positionMetres;
    flash.radiusMetres = strike.radiusMetres;
    // A bluish white, as lightning's glow in cloud is.
    flash.radiance = glm::vec3(0.85f, 0.9f, 1.0f) * (strike.radiance * brightness);
    flashes.push_back(flash);
  }
  // The brightest, as many as there is room for.
  std::sort(flashes.begin(), flashes.end(),
            [](const clouds::LightningFlash& a, const clouds::LightningFlash& b) {
              return a.radiance.b > b.radiance.b;
            });
  if (flashes.size() > capacity) flashes.resize(capacity);
  return flashes;
}

std::vector<clouds::HeroCloud> heroClouds(engine::ecs::World& world,
                                          const glm::dvec3& cameraPosition, std::uint32_t capacity,
                                          std::string* problem) {
  std::vector<clouds::HeroCloud> clouds;
  const auto* time = world.ctx().tryGet<engine::ecs::FrameTime>();
  const double now = time != nullptr ? time->elapsedSeconds : 0.0;
  world.view<const clouds::HeroCloud>().each(
      [&](engine::ecs::Entity entity, const clouds::HeroCloud& cloud) {
        clouds::HeroCloud placed = cloud;
        if (const auto* lifecycle = world.tryGet<const clouds::HeroCloudLifecycle>(entity)) {
          if (std::string error = clouds::validateHeroCloudLifecycle(*lifecycle); !error.empty()) {
            if (problem != nullptr && problem->empty()) *problem = std::move(error);
            return;
          }
          const clouds::HeroCloudLife life = clouds::heroCloudLife(*lifecycle, now);
          placed.growth = life.growth;
          placed.dissipation = life.dissipation;
        }
        // A cloud its life leaves empty takes no place among the nearest.
        if (placed.growth > 0.0f && placed.dissipation < 1.0f) clouds.push_back(placed);
      });
  const auto distance = [&](const clouds::HeroCloud& c) {
    return glm::length(c.positionMetres - cameraPosition);
  };
  std::stable_sort(clouds.begin(), clouds.end(),
                   [&](const clouds::HeroCloud& a, const clouds::HeroCloud& b) {
                     return distance(a) < distance(b);
                   });
  if (clouds.size() > capacity) clouds.resize(capacity);
  return clouds;
}

std::vector<clouds::LightningBoltSegment> lightningBolts(engine::ecs::World& world,
                                                         std::uint32_t capacity) {
  std::vector<clouds::LightningBoltSegment> pieces;
  const auto* active = world.ctx().tryGet<ActiveLightning>();
  if (active == nullptr) return pieces;
  const double now = world.ctx().get<engine::ecs::FrameTime>().elapsedSeconds;
  for (const LightningStrike& strike : active->strikes) {
    const std::vector<clouds::LightningBoltSegment> bolt =
        boltSegments(strike, strikeEnvelope(strike, now) * strike.energy);
    // Whole bolts only, while there is room.
    if (pieces.size() + bolt.size() > capacity) break;
    pieces.insert(pieces.end(), bolt.begin(), bolt.end());
  }
  return pieces;
}

clouds::FrameInputs cloudFrameInputs(engine::ecs::World& world, const HostFrame& host) {
  clouds::FrameInputs in;
  in.commandBuffer = host.commandBuffer;
  in.renderExtent = host.extent;
  in.depthView = host.depthView;
  in.depthLayout = host.depthLayout;
  in.weatherView = host.weatherView;
  in.weatherLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  in.weatherBlendView = host.weatherBlendView;
  in.weatherBlendLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  in.weatherBlend = host.weatherBlend;
  in.frameIndex = host.frameIndex;
  const float aspect = float(host.extent.width) / float(std::max(host.extent.height, 1u));
  world.view<const render::Camera>().each([&](const render::Camera& camera) {
    in.view = render::viewRotation(camera);
    in.projection = render::projectionOf(camera, aspect);
    in.cameraPosition = camera.position;
    in.reset = camera.cut;
  });
  const clouds::Settings settings = cloudSettings(world);
  const double layerMiddle = 0.5 * (double(settings.layerBottomMetres) + settings.layerTopMetres);
  const auto* transmittance = world.ctx().tryGet<render::SunTransmittance>();
  world.view<const render::Sun>().each([&](const render::Sun& sun) {
    in.sunDirection = glm::vec3(sun.direction);
    in.sunIlluminance = render::sunIlluminanceAt(sun, transmittance, layerMiddle);
    in.aerialPerspective.radianceScale = sun.illuminance;
  });
  if (const auto* ground = world.ctx().tryGet<render::GroundAlbedo>()) {
    in.groundAlbedo = ground->rgb;
  }
  if (const auto* sky = world.ctx().tryGet<render::SkyLight>()) {
    in.ambientTop = sky->zenith;
    // With the ground's albedo the module adds the ground's light itself: the horizon alone.
    in.ambientBottom = in.groundAlbedo ? sky->horizon : glm::mix(sky->horizon, sky->ground, 0.5f);
  }
  in.skyView = host.skyRadianceView;
  in.skyLayout = VK_IMAGE_LAYOUT_GENERAL;
  if (host.aerialPerspectiveView != VK_NULL_HANDLE) {
    in.aerialPerspective.view = host.aerialPerspectiveView;
    in.aerialPerspective.layout = VK_IMAGE_LAYOUT_GENERAL;
    in.aerialPerspective.slices = host.aerialPerspectiveSlices;
    in.aerialPerspective.rangeMetres = host.aerialPerspectiveRangeMetres;
    in.aerialPerspective.rayleighScatteringPerMetre = host.hazeRayleighPerMetre;
    in.aerialPerspective.mieScatteringPerMetre = host.hazeMiePerMetre;
    in.aerialPerspective.miePhaseG = host.hazeMiePhaseG;
  }
  if (const auto* time = world.ctx().tryGet<engine::ecs::FrameTime>()) {
    in.timeSeconds = time->elapsedSeconds;
  }
  // Changing weather: the clouds drift as far as its wind, blended, has carried them.
  world.view<const CloudLayer, const CloudWeather>().each(
      [&](const CloudLayer&, const CloudWeather& w) {
        in.windDisplacementMetres = w.timeline.windDisplacementAt(in.timeSeconds);
      });
  // The ground, when the scene's terrain casts shadows: mountains shade the clouds (and the
  // terrain itself, through the shadow map).
  if (const auto* ground = world.ctx().tryGet<render::TerrainHeightfield>()) {
    in.terrain.heightView = ground->view;
    in.terrain.originMetres = ground->originMetres;
    in.terrain.sizeMetres = ground->sizeMetres;
    in.terrain.minAltitudeMetres = ground->minAltitudeMetres;
    in.terrain.maxAltitudeMetres = ground->maxAltitudeMetres;
  }
  return in;
}

}  // namespace clouds::ecs
