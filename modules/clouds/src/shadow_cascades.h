#pragma once
// The cloud shadow map's cascades as plain logic (unit-tested without a GPU): where each
// cascade lies, which cascades a frame remakes, and the lookup parameters hosts read
// (fxcontracts/cloud_shadow.h).
//
// Placement: cascade c is a square of side shadowNearSideMetres x ratio^c seen along the light
// direction, on a grid of whole texels fixed in the world (plane coordinates along U and V, in
// double precision), centred on the texel nearest to the camera's focus: the camera itself, or
// the cloud base below it when it flies higher. Moving the camera moves the square by whole
// texels, so every texel keeps the very same sun ray and the map does not swim.
//
// Refresh: a cascade is remade in turn (the finest every other turn, the others round-robin),
// shadowCascadesPerFrame per frame, or one turn over shadowFramesPerCascade frames in slices
// of rows (CascadeSlice); after all of them were remade at once the turns begin again. A
// cascade is remade at once when it was never made, on a camera
// cut, when the settings, the weather map or the terrain changed, when the camera's focus left the
// middle half of it, when the sun turned more than Settings::relightResetDegrees since, or when the
// time since it was made is negative or long. Between refreshes the wind's drift of the clouds
// since the cascade was made moves its lookup, so shadows travel with the clouds.
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "cloud_types.h"
#include "clouds/clouds.h"
#include "fxcontracts/cloud_shadow.h"
#include "painted_weather.h"
#include "weather_regions.h"

namespace clouds::detail {

// An orthonormal frame for the shadow rays: L towards the sun (its elevation raised to the
// map's minimum), U horizontal and perpendicular to it, V = L x U.
struct ShadowBasis {
  glm::dvec3 u{1.0, 0.0, 0.0};
  glm::dvec3 v{0.0, 0.0, 1.0};
  glm::dvec3 light{0.0, 1.0, 0.0};
};
ShadowBasis shadowBasis(const glm::vec3& sunDirection);

// Side (m) of cascade `c`.
double cascadeSideMetres(const Settings& settings, std::uint32_t c);

// The order in which cascades take their turns: the finest every other turn, the others in
// turn between (for one cascade, always it).
std::uint32_t cascadeForTurn(std::uint64_t turn, std::uint32_t cascades);

// A cascade to make this frame.
struct CascadeJob {
  std::uint32_t cascade = 0;
  ShadowBasis basis;
  glm::i64vec2 cornerTexel{0, 0};  // world grid index (along U, V) of the cascade's texel 0
  double texelMetres = 0.0;
  // The cascade's terrain channel was made over these very rays and this terrain: keep it
  // (the terrain does not move), no terrain pass for it.
  bool keepTerrain = false;
};

// A slice of the cascade in the making (Settings::shadowFramesPerCascade > 1): its rows
// [firstRow, firstRow + rowCount), made into the spare cascade image with the field and camera
// of the frame of its first slice, so that every slice makes what that frame would have made.
struct CascadeSlice {
  CascadeJob job;
  glm::dvec3 cameraPosition{0.0};  // the first slice's camera: constants are relative to it
  std::uint32_t firstRow = 0;
  std::uint32_t rowCount = 0;
  bool first = false;  // this frame's field is the one the later slices use
  bool last = false;   // the cascade is done: copied into the atlas this frame
};

// What a frame makes: the cascades that must be remade at once (whole, into the atlas), then
// those whose turn it is (whole, or a slice of the one in the making).
struct ShadowPlan {
  std::vector<CascadeJob> jobs;
  std::optional<CascadeSlice> slice;
  bool abandonSlices = false;  // the cascade in the making is dropped (remade at once instead)
  std::uint64_t nextTurn = 0;  // the turn the next frame starts from
};

// The shadow-map shader's push constants for `job`, camera-relative.
shader::ShadowMapConstants shadowMapConstants(const CascadeJob& job,
                                              const glm::dvec3& cameraPosition,
                                              const Settings& settings);

// The terrain-shadow shader's push constants for `job` (FrameInputs::terrain), camera-relative.
shader::TerrainShadowConstants terrainShadowConstants(const CascadeJob& job,
                                                      const FrameInputs& inputs,
                                                      const Settings& settings);

class ShadowCascades {
 public:
  ShadowPlan plan(const FrameInputs& inputs, const Settings& settings) const;
  // The plan's jobs were recorded in this frame.
  void commit(const ShadowPlan& plan, const FrameInputs& inputs, const Settings& settings);
  // The map's contents are gone (its image was replaced): everything is remade next time.
  void forget() {
    made_ = {};
    hasTerrain_ = {};
    building_.reset();
  }

  // The lookup parameters relative to the camera at `cameraPosition`, the wind having carried
  // the clouds to `windDisplacementMetres` (wind_displacement.h).
  ShadowMapParameters parameters(const glm::dvec3& cameraPosition,
                                 const glm::dvec2& windDisplacementMetres,
                                 const Settings& settings) const;

 private:
  struct Made {
    bool valid = false;
    ShadowBasis basis;
    glm::i64vec2 cornerTexel{0, 0};
    double texelMetres = 0.0;
    double timeSeconds = 0.0;
    glm::dvec2 windDisplacement{0.0};  // of the clouds it holds (x, z m)
  };
  CascadeJob placement(std::uint32_t c, const FrameInputs& inputs, const Settings& settings) const;
  bool stale(const Made& made, const CascadeJob& now, const FrameInputs& inputs,
             const Settings& settings) const;
  // The next slice of the cascade in the making, or of a new one whose turn it is.
  CascadeSlice nextSlice(const FrameInputs& inputs, const Settings& settings,
                         ShadowPlan& plan) const;

  // A cascade made over several frames, between its first slice and its last.
  struct Building {
    CascadeSlice first;  // its first slice (the job, the camera)
    std::uint32_t rowsDone = 0;
    double timeSeconds = 0.0;  // of the first slice: the clouds it holds
    glm::dvec2 windDisplacement{0.0};
  };

  std::array<Made, fxcontracts::shader::kCloudShadowMaxCascades> made_{};
  // Whether each cascade was made with a terrain (its channel then holds that terrain's shadow
  // over the rays in made_).
  std::array<bool, fxcontracts::shader::kCloudShadowMaxCascades> hasTerrain_{};
  std::optional<Building> building_;
  std::uint64_t turn_ = 0;
  Settings settings_{};  // those the made cascades were made with
  PaintedWeather painted_;
  std::vector<WeatherRegion> regions_;
  FrameInputs::Terrain terrain_{};  // the terrain the made cascades were made with
};

}  // namespace clouds::detail
