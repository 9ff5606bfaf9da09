// libFuzzer target: the NVDF reader (clouds/nvdf.h; hero clouds). It answers malformed input
// with a clouds::Error (InvalidAsset) naming the file, never by throwing; anything else (a
// message without the file, a crash, a sanitizer report, a hang) is a finding.
#include <cstdio>
#include <cstdlib>

#include "clouds/nvdf.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file = fuzz::inputFile(".nvdf");
  fuzz::writeInput(file, data, size);
  clouds::Error error;
  const std::optional<clouds::NvdfVolume> volume = clouds::readNvdf(file, &error);
  if (volume) {
    // Whatever loads is consistent.
    if (!clouds::validateNvdf(*volume).empty()) std::abort();
    return 0;
  }
  if (error.code != clouds::ErrorCode::InvalidAsset ||
      error.message.find(file.filename().string()) == std::string::npos) {
    std::fprintf(stderr, "fuzz: the error does not name the file: %s\n", error.message.c_str());
    std::abort();
  }
  return 0;
}
