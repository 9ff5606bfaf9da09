#include "terrain_params.h"

#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/file_io.h"
#include "json_fields.h"

namespace terrain {
namespace {

// Wavelengths shorter than a few metres would alias against any grid this tool builds.
constexpr double kMinWavelength = 10.0;
constexpr double kMaxWavelength = 1.0e6;
constexpr double kMinHeight = -1000.0;
constexpr double kMaxHeight = 10000.0;

PlainsParams readPlains(JsonFields fields) {
  PlainsParams p;
  p.amplitudeMetres = fields.number("amplitudeMetres", 0.0, 2000.0);
  p.wavelengthMetres = fields.number("wavelengthMetres", kMinWavelength, kMaxWavelength);
  p.octaves = static_cast<int>(fields.integer("octaves", 1, 12));
  return p;
}

MountainParams readMountains(JsonFields fields) {
  MountainParams p;
  p.heightMetres = fields.number("heightMetres", 0.0, 9000.0);
  p.wavelengthMetres = fields.number("wavelengthMetres", kMinWavelength, kMaxWavelength);
  p.octaves = static_cast<int>(fields.integer("octaves", 1, 16));
  p.lacunarity = fields.number("lacunarity", 1.1, 4.0);
  p.gain = fields.number("gain", 0.05, 0.95);
  p.sharpness = fields.number("sharpness", 0.5, 4.0);
  p.erosion = fields.number("erosion", 0.0, 10.0);
  return p;
}

RangeParams readRanges(JsonFields fields, double sizeMetres) {
  RangeParams p;
  p.wavelengthMetres = fields.number("wavelengthMetres", kMinWavelength, kMaxWavelength);
  p.threshold = fields.number("threshold", 0.0, 1.0);
  p.softness = fields.number("softness", 0.001, 1.0);
  p.edgeFalloffMetres = fields.number("edgeFalloffMetres", 0.0, sizeMetres * 0.5);
  return p;
}

ValleyParams readValleys(JsonFields fields) {
  ValleyParams p;
  p.wavelengthMetres = fields.number("wavelengthMetres", kMinWavelength, kMaxWavelength);
  p.width = fields.number("width", 0.0, 1.0);
  p.riverWidth = fields.number("riverWidth", 0.0, 1.0);
  p.riverDepthMetres = fields.number("riverDepthMetres", 0.0, 1000.0);
  return p;
}

CoverRules readCover(JsonFields fields) {
  CoverRules r;
  r.grassColour = fields.linearRgb("grassColour");
  r.rockColour = fields.linearRgb("rockColour");
  r.snowColour = fields.linearRgb("snowColour");
  r.rockMinSlopeDegrees = fields.number("rockMinSlopeDegrees", 0.0, 90.0);
  r.grassMaxHeightMetres = fields.number("grassMaxHeightMetres", kMinHeight, kMaxHeight);
  r.snowMinHeightMetres = fields.number("snowMinHeightMetres", kMinHeight, kMaxHeight);
  r.snowMaxSlopeDegrees = fields.number("snowMaxSlopeDegrees", 0.0, 90.0);
  return r;
}

}  // namespace

TerrainParams loadTerrainParams(const std::filesystem::path& path) {
  const std::string file = path.string();
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(engine::readTextFile(path));
  } catch (const nlohmann::json::parse_error& e) {
    throw engine::Error(file + ": invalid JSON: " + e.what());
  }

  JsonFields fields(root, file, "",
                    {"sizeMetres", "gridResolution", "seed", "baseHeightMetres", "plains",
                     "mountains", "ranges", "valleys", "cover"});
  TerrainParams p;
  p.sizeMetres = fields.number("sizeMetres", 1000.0, 200000.0);
  p.gridResolution = static_cast<int>(fields.integer("gridResolution", 3, 2049));
  p.seed = static_cast<std::uint32_t>(fields.integer("seed", 0, UINT32_MAX));
  p.baseHeightMetres = fields.number("baseHeightMetres", kMinHeight, kMaxHeight);
  p.plains =
      readPlains(fields.object("plains", {"amplitudeMetres", "wavelengthMetres", "octaves"}));
  p.mountains =
      readMountains(fields.object("mountains", {"heightMetres", "wavelengthMetres", "octaves",
                                                "lacunarity", "gain", "sharpness", "erosion"}));
  p.ranges = readRanges(
      fields.object("ranges", {"wavelengthMetres", "threshold", "softness", "edgeFalloffMetres"}),
      p.sizeMetres);
  p.valleys = readValleys(
      fields.object("valleys", {"wavelengthMetres", "width", "riverWidth", "riverDepthMetres"}));
  p.cover = readCover(fields.object(
      "cover", {"grassColour", "rockColour", "snowColour", "rockMinSlopeDegrees",
                "grassMaxHeightMetres", "snowMinHeightMetres", "snowMaxSlopeDegrees"}));
  return p;
}

}  // namespace terrain
