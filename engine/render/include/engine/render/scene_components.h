#pragma once
// Components every renderer of the engine understands, independent of any game: the viewpoint,
// the sun and what the air lets through of it, the sky's light, fog. Effect adapters read and
// provide these; games write them.
#include <vulkan/vulkan.h>

#include <functional>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace engine::render {

// The viewpoint. World: metres, Y up, a flat map tens of kilometres wide, so the position is
// double precision and rendering is camera-relative. `orientation` rotates camera space (looking
// down -Z with +Y up) into world space.
struct Camera {
  glm::dvec3 position{0.0, 2.0, 0.0};
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  float verticalFovRadians = 1.1f;
  float nearMetres = 0.5f;
  bool cut = false;  // the camera jumped this frame: temporal effects drop their history
};

glm::dvec3 forwardOf(const Camera& camera);
glm::dvec3 upOf(const Camera& camera);
// World -> view with the camera at the origin (camera-relative rendering).
glm::mat4 viewRotation(const Camera& camera);
// View -> clip for an image of `aspect` = width / height: reversed-Z, infinite far plane
// (camera_math.h). Every pass that draws or traces with the camera uses this one.
glm::mat4 projectionOf(const Camera& camera, float aspect);

// Units: the renderer's radiometric unit is the kilo-candela per square metre (kcd/m^2) for
// radiance and the kilolux (klx) for illuminance, linear Rec. 709 RGB whose luminance weights
// are (0.2126, 0.7152, 0.0722). Sunlight above the air is about 127 klx, a clear noon sky a few
// kcd/m^2; the tonemap's exposure (exposure.h) brings that to the display.

// Luminance of linear Rec. 709 RGB, in the unit of the RGB (kcd/m^2 for radiance).
inline double luminance(const glm::dvec3& rgb) {
  return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
}

// The sun as a directional light.
struct Sun {
  glm::dvec3 direction{0.0, 1.0, 0.0};  // unit, towards the sun
  glm::vec3 illuminance{127.0f};        // klx, RGB, at the top of the atmosphere: what reaches
                                        //   a point is this times SunTransmittance there
};

// Context singleton: how much of the sun's light the scene's air lets through to an altitude.
// An effect that models the air provides it when the scene has one; a game without one
// provides its own (the sample's analytic air mass). Absent: nothing is in the way.
struct SunTransmittance {
  // RGB transmittance in [0, 1] from the top of the atmosphere to `altitudeMetres` at the
  // camera's place on the planet, for a sun towards `sunDirection`; 0 below the horizon.
  std::function<glm::vec3(double altitudeMetres, const glm::dvec3& sunDirection)> at;
};

// The sun's illuminance reaching `altitudeMetres` (klx, RGB): Sun::illuminance through the
// world's SunTransmittance, if it has one.
glm::vec3 sunIlluminanceAt(const Sun& sun, const SunTransmittance* transmittance,
                           double altitudeMetres);

// Context singleton: sky radiance (kcd/m^2, RGB) for ambient light: the sky straight up, at the
// horizon, and the light coming up from below (ground and air). An effect that draws the sky
// measures it from its sky; a game without one sets it itself.
struct SkyLight {
  glm::vec3 zenith{1.5f, 2.8f, 6.5f};
  glm::vec3 horizon{5.5f, 6.2f, 7.5f};
  glm::vec3 ground{1.2f, 1.2f, 1.0f};
};

// Context singleton: the sky light as the scene's weather makes it, the drawn sky with what
// covers it: the same regions and units as SkyLight, measured by the effect that renders the
// cover. It lights the scene's ambient in SkyLight's place (SkyLight stays what the sky is
// drawn with); absent, SkyLight lights it. Seen from under the cover: a viewer above it sees
// SkyLight's clear sky, and one inside it something between (an exposure meter blends them by
// altitude, exposure.h).
struct CoveredSkyLight {
  SkyLight light;
  // A horizontal surface's irradiance / pi under the cover (kcd/m^2, RGB): the cosine-weighted
  // mean of the covered sky, measured whole, not estimated from its regions.
  glm::vec3 irradianceOverPi{0.0f};
  // The share of the sun's light, past the air (SunTransmittance), that the cover lets through
  // to the camera, and the share of the ground around the camera in the sun, in [0, 1].
  float sunAtCamera = 1.0f;
  float sunAround = 1.0f;
  double seenFromMetres = 0.0;    // the altitude the covered sky was seen from
  double clearAboveMetres = 0.0;  // above this altitude nothing covers the sky
};

// Context singleton: the Lambertian albedo of the scene's ground at large (RGB, [0, 1]), for
// light bounced off it (e.g. onto what floats above it). An effect that models the air
// publishes the one its sky is made with; absent, effects do without the ground's light.
struct GroundAlbedo {
  glm::vec3 rgb{0.3f};
};

// Context singleton: the scene's ground as a heightfield on the GPU, for effects that need its
// shape rather than its triangles (e.g. to shadow with it). Published by whoever owns the
// terrain, for as long as the image lives; absent when nothing should be shadowed by the
// terrain. The image is static, in SHADER_READ_ONLY_OPTIMAL, one float channel that filters
// linearly: altitude (m), texel (0, 0) at `originMetres`, u along +x and v along +z.
struct TerrainHeightfield {
  VkImageView view = VK_NULL_HANDLE;
  glm::dvec2 originMetres{0.0};  // world (x, z) of the image's corner
  glm::dvec2 sizeMetres{0.0};    // world extent along x and z
  float minAltitudeMetres = 0.0f;
  float maxAltitudeMetres = 0.0f;
};

// Context singleton: exponential distance fog towards the sky, the cheap alternative for scenes
// without an effect that models the air's scattering.
struct Fog {
  float densityPerMetre = 0.0f;  // 0: no fog
};

}  // namespace engine::render
