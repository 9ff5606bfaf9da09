#pragma once
// Turns a SceneDescription into a running world: entities and components (the player's camera
// and aircraft, the sun and its clock, the terrain, the cloud layer), context singletons
// (input, frame time, atmosphere, terrain height field) and the systems and modules the scene
// calls for. A scene without clouds gets no clouds module; one without terrain gets no terrain.
//
// Two steps, so that every file is read and checked before a window or device exists, and the
// modules that create GPU objects install after the renderer published its device:
//   loadTerrain()    the scene's terrain mesh (or --terrain's), placed in the world;
//   populateScene()  the world, with engine::render::RenderDevice already in its context.
#include <filesystem>
#include <memory>

#include "clouds/clouds.h"
#include "clouds/nvdf.h"
#include "engine/assets/gltf_loader.h"
#include "engine/ecs/app.h"
#include "scene/scene_description.h"

namespace sample {

// The loaded terrain mesh (placed in the world), for the renderer to upload.
struct TerrainMesh {
  std::shared_ptr<const engine::assets::MeshData> mesh;
  bool castsShadows = true;              // TerrainDescription::castsShadows
  std::optional<double> snowlineMetres;  // TerrainDescription::snowlineMetres
  bool closeDetail = true;               // TerrainDescription::closeDetail
};

struct LoadedTerrain {
  std::filesystem::path path;
  std::shared_ptr<engine::assets::MeshData> mesh;
};

// The scene's terrain, loaded, validated and placed; none when the scene has none and there
// is no override. `defaultTerrain` is what "gltf": "default" means (the build-time generated
// terrain); `terrainOverride`, when set, replaces the scene's terrain (the --terrain option).
// Throws engine::Error naming the file and the problem.
std::optional<LoadedTerrain> loadTerrain(
    const SceneDescription& scene, const std::filesystem::path& defaultTerrain,
    const std::optional<std::filesystem::path>& terrainOverride);

// The hero clouds' assets, read and checked, and where the scene places them.
struct PlacedHeroCloud {
  clouds::HeroCloud cloud;                              // `asset` indexes LoadedHeroClouds::assets
  std::optional<clouds::HeroCloudLifecycle> lifecycle;  // none: always as authored
};
struct LoadedHeroClouds {
  std::vector<std::shared_ptr<const clouds::NvdfVolume>> assets;
  std::vector<PlacedHeroCloud> placements;
};

// The scene's hero clouds (shipped ones from `shippedDir`, the baked assets_src/hero_clouds)
// and `userCloud` (the --cloud option: an .nvdf or OpenVDB file), placed in front of the
// camera's start and added to `scene`'s hero clouds where it was placed (so a saved scene
// keeps it). Throws engine::Error naming the file and the problem.
LoadedHeroClouds loadHeroClouds(SceneDescription& scene, const std::filesystem::path& shippedDir,
                                const std::optional<std::filesystem::path>& userCloud);

void populateScene(engine::ecs::App& app, const SceneDescription& scene,
                   const std::optional<LoadedTerrain>& terrain,
                   const LoadedHeroClouds& heroClouds = {});

}  // namespace sample
