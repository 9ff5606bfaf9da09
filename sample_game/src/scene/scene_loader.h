#pragma once
// Turns a SceneDescription into a running world: entities and components (the player's camera
// and aircraft, the sun and its clock, the terrain, the cloud layer), context singletons
// (input, frame time, atmosphere, terrain height field) and the systems and modules the scene
// calls for. A scene without clouds gets no clouds module; one without terrain gets no terrain.
#include <filesystem>
#include <memory>

#include "engine/assets/gltf_loader.h"
#include "engine/ecs/app.h"
#include "scene/scene_description.h"

namespace sample {

// The loaded terrain mesh (placed in the world), for the renderer to upload.
struct TerrainMesh {
  std::shared_ptr<const engine::assets::MeshData> mesh;
};

// `defaultTerrain` is what "gltf": "default" means (the build-time generated terrain);
// `terrainOverride`, when set, replaces the scene's terrain (the --terrain option).
void populateScene(engine::ecs::App& app, const SceneDescription& scene,
                   const std::filesystem::path& defaultTerrain,
                   const std::optional<std::filesystem::path>& terrainOverride);

}  // namespace sample
