// libFuzzer target: the headless input-script reader (tests/sample_game/scripts/*.json).
#include "fuzz_input.h"
#include "game/input_script.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz::loadInput(".json", data, size, [](const std::filesystem::path& file) {
    sample::InputScript::load(file);
  });
}
