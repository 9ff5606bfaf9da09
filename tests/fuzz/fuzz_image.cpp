// libFuzzer target: the image reader (weather maps and other PNGs go through it; OpenImageIO
// itself is not instrumented, so this checks the wrapper's handling of what it returns).
#include "engine/assets/image_io.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz::loadInput(".png", data, size, [](const std::filesystem::path& file) {
    engine::assets::readImage(file);
  });
}
