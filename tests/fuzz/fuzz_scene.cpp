// libFuzzer target: the scene JSON reader (assets_src/scenes/*.json).
#include "fuzz_input.h"
#include "scene/scene_description.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz::loadInput(".json", data, size, [](const std::filesystem::path& file) {
    sample::loadSceneDescription(file);
  });
}
