// cloudscape sample: see README.md for the controls and the command line.
#include <cstdio>
#include <exception>

#include "engine/core/error.h"
#include "options.h"
#include "runtime.h"

int main(int argc, char** argv) {
  const sample::ParseResult parsed = sample::parseOptions(argc, argv);
  if (!parsed.options) return parsed.exitCode;
  try {
    return sample::run(*parsed.options);
  } catch (const engine::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected error: %s\n", e.what());
    return 2;
  }
}
