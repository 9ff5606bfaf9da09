// terrain_gen: writes a procedural terrain as glTF 2.0 at build time, or checks one.
//   terrain_gen <params.terrain.json> <out.gltf>     writes out.gltf and out.bin
//   terrain_gen --check <out.gltf> [--min-peak M] [--max-floor M]
// Exit codes: 0 success, 1 bad input or a failed check, 2 wrong usage.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/error.h"
#include "gltf_writer.h"
#include "heightfield.h"
#include "terrain_check.h"
#include "terrain_mesh.h"
#include "terrain_params.h"

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

void printUsage(std::FILE* out) {
  std::fputs(
      "usage: terrain_gen <params.terrain.json> <out.gltf>\n"
      "       terrain_gen --check <terrain.gltf> [--min-peak METRES] [--max-floor METRES]\n"
      "Generates a terrain glTF (out.gltf + out.bin) from a parameter file, or verifies one\n"
      "(counts, bounds, unit normals, winding, index range, highest point above --min-peak\n"
      "(default 1500), lowest below --max-floor (default 400)) and prints a summary.\n",
      out);
}

int generate(const std::string& paramsPath, const std::string& outPath) {
  const auto start = std::chrono::steady_clock::now();
  const terrain::TerrainParams params = terrain::loadTerrainParams(paramsPath);
  const terrain::Heightfield field = terrain::synthesizeHeightfield(params);
  const terrain::TerrainMesh mesh = terrain::buildTerrainMesh(field, params.cover);
  terrain::writeTerrainGltf(mesh, params.cover, outPath);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  std::printf("terrain_gen: wrote %s (%zu vertices, %zu triangles) in %.2f s\n", outPath.c_str(),
              mesh.positions.size(), mesh.indices.size() / 3, seconds.count());
  return 0;
}

double metresArgument(const std::string& flag, const std::string& value) {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0') throw engine::Error(flag + ": not a number: " + value);
  return v;
}

int check(const std::vector<std::string>& args) {
  terrain::CheckThresholds thresholds;
  std::string path;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const bool hasValue = i + 1 < args.size();
    if (args[i] == "--min-peak" && hasValue) {
      thresholds.minPeakMetres = metresArgument(args[i], args[i + 1]);
      ++i;
    } else if (args[i] == "--max-floor" && hasValue) {
      thresholds.maxFloorMetres = metresArgument(args[i], args[i + 1]);
      ++i;
    } else if (path.empty() && !args[i].starts_with("--")) {
      path = args[i];
    } else {
      printUsage(stderr);
      return kExitUsage;
    }
  }
  if (path.empty()) {
    printUsage(stderr);
    return kExitUsage;
  }
  const terrain::CheckReport report = terrain::checkTerrainGltf(path, thresholds);
  // One report on stdout, failures first, so a CTest log reads top to bottom.
  std::printf("%s: %s\n", path.c_str(), report.failures.empty() ? "OK" : "FAILED");
  for (const std::string& line : report.failures) std::printf("  FAIL: %s\n", line.c_str());
  for (const std::string& line : report.summary) std::printf("  %s\n", line.c_str());
  return report.failures.empty() ? 0 : kExitFailure;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
      printUsage(stdout);
      return 0;
    }
    if (!args.empty() && args[0] == "--check") {
      return check(std::vector<std::string>(args.begin() + 1, args.end()));
    }
    if (args.size() != 2 || args[0].starts_with("-") || args[1].starts_with("-")) {
      printUsage(stderr);
      return kExitUsage;
    }
    return generate(args[0], args[1]);
  } catch (const std::exception& e) {
    // engine::Error messages already name the file and field; anything else is unexpected.
    std::fprintf(stderr, "terrain_gen: %s\n", e.what());
    return kExitFailure;
  }
}
