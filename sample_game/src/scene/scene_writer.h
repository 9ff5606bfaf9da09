#pragma once
// A scene description back as scene JSON: what loadSceneDescription() reads, every field it
// reads written out (files as absolute paths, a storm's cells as found, an atmosphere preset as
// its parameters), so that the file loads back to the same description and renders the same
// frames. The settings panel saves what the player made with it.
#include <filesystem>
#include <string>

#include "scene/scene_description.h"

namespace sample {

std::string sceneJson(const SceneDescription& scene);

// Writes sceneJson(scene) to `file`. Throws engine::Error naming the file when it cannot.
void writeSceneFile(const SceneDescription& scene, const std::filesystem::path& file);

}  // namespace sample
