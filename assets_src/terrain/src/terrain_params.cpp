#include "terrain_params.h"

#include <string>

#include "engine/core/json_reader.h"

namespace terrain {
namespace {

// Wavelengths shorter than a few metres would alias against any grid this tool builds.
constexpr double kMinWavelength = 10.0;
constexpr double kMaxWavelength = 1.0e6;
constexpr double kMinHeight = -1000.0;
constexpr double kMaxHeight = 10000.0;

PlainsParams readPlains(const engine::JsonReader& fields) {
  PlainsParams p;
  p.amplitudeMetres = fields.number("amplitudeMetres", 0.0, 2000.0);
  p.wavelengthMetres = fields.number("wavelengthMetres", kMinWavelength, kMaxWavelength);
  p.octaves = static_cast<int>(fields.integer("octaves", 1, 12));
  fields.finish();
  return p;
}

MountainParams readMountains(const engine::JsonReader& fields) {
  MountainParams p;
  p.heightMetres = fields.number("heightMetres", 0.0, 9000.0);
  p.wavelengthMetres = fields.number("wavelengthMetres", kMinWavelength, kMaxWavelength);
  p.octaves = static_cast<int>(fields.integer("octaves", 1, 16));
  p.lacunarity = fields.number("lacunarity", 1.1, 4.0);
  p.gain = fields.number("gain", 0.05, 0.95);
  p.sharpness = fields.number("sharpness", 0.5, 4.0);
  p.erosion = fields.number("erosion", 0.0, 10.0);
  fields.finish();
  return p;
}

RangeParams readRanges(const engine::JsonReader& fields, double sizeMetres) {
  RangeParams p;
  p.wavelengthMetres = fields.number("wavelengthMetres", kMinWavelength, kMaxWavelength);
  p.threshold = fields.number("threshold", 0.0, 1.0);
  p.softness = fields.number("softness", 0.001, 1.0);
  p.edgeFalloffMetres = fields.number("edgeFalloffMetres", 0.0, sizeMetres * 0.5);
  fields.finish();
  return p;
}

ValleyParams readValleys(const engine::JsonReader& fields) {
  ValleyParams p;
  p.wavelengthMetres = fields.number("wavelengthMetres", kMinWavelength, kMaxWavelength);
  p.width = fields.number("width", 0.0, 1.0);
  p.riverWidth = fields.number("riverWidth", 0.0, 1.0);
  p.riverDepthMetres = fields.number("riverDepthMetres", 0.0, 1000.0);
  fields.finish();
  return p;
}

// A linear RGB colour: three numbers in [0, 1].
glm::vec3 linearRgb(const engine::JsonReader& fields, const std::string& key) {
  return glm::vec3(fields.vec3(key, 0.0, 1.0));
}

CoverRules readCover(const engine::JsonReader& fields) {
  CoverRules r;
  r.grassColour = linearRgb(fields, "grassColour");
  r.rockColour = linearRgb(fields, "rockColour");
  r.snowColour = linearRgb(fields, "snowColour");
  r.rockMinSlopeDegrees = fields.number("rockMinSlopeDegrees", 0.0, 90.0);
  r.grassMaxHeightMetres = fields.number("grassMaxHeightMetres", kMinHeight, kMaxHeight);
  r.snowMinHeightMetres = fields.number("snowMinHeightMetres", kMinHeight, kMaxHeight);
  r.snowMaxSlopeDegrees = fields.number("snowMaxSlopeDegrees", 0.0, 90.0);
  fields.finish();
  return r;
}

}  // namespace

TerrainParams loadTerrainParams(const std::filesystem::path& path) {
  const nlohmann::json root = engine::JsonReader::parseFile(path);
  const engine::JsonReader fields(root, path.string());
  TerrainParams p;
  p.sizeMetres = fields.number("sizeMetres", 1000.0, 200000.0);
  p.gridResolution = static_cast<int>(fields.integer("gridResolution", 3, 2049));
  p.seed = static_cast<std::uint32_t>(fields.integer("seed", 0, UINT32_MAX));
  p.baseHeightMetres = fields.number("baseHeightMetres", kMinHeight, kMaxHeight);
  p.plains = readPlains(fields.object("plains"));
  p.mountains = readMountains(fields.object("mountains"));
  p.ranges = readRanges(fields.object("ranges"), p.sizeMetres);
  p.valleys = readValleys(fields.object("valleys"));
  p.cover = readCover(fields.object("cover"));
  fields.finish();
  return p;
}

}  // namespace terrain
