#pragma once
// The loaders under fuzzing read files (that is their public contract), so each input is
// written to one file per process, with the extension the loader dispatches on, and loaded
// from there. A loader may only answer malformed input with engine::Error naming that file;
// anything else (another exception, a message without the file, a crash, a sanitizer report,
// a hang) is a finding.
#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/error.h"

namespace fuzz {

inline std::filesystem::path inputFile(const char* extension) {
  return std::filesystem::temp_directory_path() /
         ("cloudscape_fuzz_" + std::to_string(::getpid()) + extension);
}

inline void writeInput(const std::filesystem::path& file, const std::uint8_t* data,
                       std::size_t size) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", file.c_str());
    std::abort();
  }
}

// Runs `load` on the input; aborts (a finding) unless it succeeds or throws engine::Error whose
// message names the file.
template <typename Load>
int loadInput(const char* extension, const std::uint8_t* data, std::size_t size, Load load) {
  static const std::filesystem::path file = inputFile(extension);
  writeInput(file, data, size);
  // CLOUDSCAPE_FUZZ_VERBOSE=1: print what each input got (to check that seeds load).
  static const bool verbose = std::getenv("CLOUDSCAPE_FUZZ_VERBOSE") != nullptr;
  try {
    load(file);
    if (verbose) std::fprintf(stderr, "fuzz: loaded\n");
  } catch (const engine::Error& e) {
    if (verbose) std::fprintf(stderr, "fuzz: rejected: %s\n", e.what());
    if (std::string(e.what()).find(file.filename().string()) == std::string::npos) {
      std::fprintf(stderr, "fuzz: the error does not name the file: %s\n", e.what());
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: not an engine::Error: %s\n", e.what());
    std::abort();
  }
  return 0;
}

}  // namespace fuzz
