#include "bench_ladder.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "bench_report.h"
#include "engine/core/error.h"

namespace bench {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle),
                   values.end());
  return values[middle];
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  return fields;
}

double number(const std::string& text, const std::filesystem::path& file, std::size_t line,
              const char* column) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  throw engine::Error(file.string() + ":" + std::to_string(line) + ": " + column + " '" + text +
                      "' is not a number");
}

}  // namespace

std::vector<LadderStep> ladderSteps(const BenchResults& results) {
  std::vector<const BenchConfig*> presets;
  for (const BenchConfig& c : results.configs) {
    if (c.preset && aggregateStatic(results, c.name).milliseconds > 0.0) presets.push_back(&c);
  }
  std::sort(presets.begin(), presets.end(),
            [](const BenchConfig* a, const BenchConfig* b) { return a->quality < b->quality; });
  std::vector<LadderStep> steps;
  for (std::size_t i = 1; i < presets.size(); ++i) {
    const Aggregate lower = aggregateStatic(results, presets[i - 1]->name);
    const Aggregate upper = aggregateStatic(results, presets[i]->name);
    steps.push_back(LadderStep{presets[i - 1]->name, presets[i]->name,
                               lower.milliseconds / upper.milliseconds, upper.psnr - lower.psnr});
  }
  return steps;
}

GovernedFlight readGovernedFlight(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw engine::Error(file.string() + ": cannot read the frame series");
  // The series has grown columns at its end (the clouds' history, the exposure): a flight is
  // measured by the first seven, and each row has as many fields as the header.
  const std::string expected = "frame,seconds,wall_ms,gpu_ms,cloud_preset,governor,target_ms";
  std::string line;
  if (!std::getline(in, line) || line.compare(0, expected.size(), expected) != 0 ||
      (line.size() > expected.size() && line[expected.size()] != ',')) {
    throw engine::Error(file.string() + ":1: the header does not start with '" + expected +
                        "' (sample_game --frame-series writes it)");
  }
  const std::size_t fields = splitCsv(line).size();
  GovernedFlight flight;
  std::vector<double> wall;
  std::vector<double> stretch;
  double firstSeconds = -1.0, lastSeconds = 0.0, stretchStart = 0.0;
  std::string preset;
  std::size_t lastChange = 0;
  for (std::size_t lineNumber = 2; std::getline(in, line); ++lineNumber) {
    const std::vector<std::string> f = splitCsv(line);
    if (f.size() != fields) {
      throw engine::Error(file.string() + ":" + std::to_string(lineNumber) + ": " +
                          std::to_string(fields) + " fields expected, " + std::to_string(f.size()) +
                          " found");
    }
    const double seconds = number(f[1], file, lineNumber, "seconds");
    const double wallMs = number(f[2], file, lineNumber, "wall_ms");
    const double target = number(f[6], file, lineNumber, "target_ms");
    // Not governed, or before the governor's first judgement (its window filling).
    if (f[5] == "off" || f[5] == "starting" || target <= 0.0) continue;
    if (firstSeconds < 0.0) {
      firstSeconds = stretchStart = seconds;
      flight.targetMs = target;
    }
    if (f[4] != preset) {
      if (!preset.empty()) {
        const std::size_t gap = flight.frames - lastChange;
        if (flight.presetChanges > 0) {
          flight.shortestGapFrames =
              flight.shortestGapFrames == 0 ? gap : std::min(flight.shortestGapFrames, gap);
        }
        ++flight.presetChanges;
        lastChange = flight.frames;
      }
      preset = f[4];
      const auto known = std::find_if(flight.framesPerPreset.begin(), flight.framesPerPreset.end(),
                                      [&](const auto& p) { return p.first == preset; });
      if (known == flight.framesPerPreset.end()) flight.framesPerPreset.emplace_back(preset, 0);
    }
    for (auto& [name, count] : flight.framesPerPreset) count += name == preset ? 1u : 0u;
    if (seconds - stretchStart >= 10.0) {
      flight.tenSecondMedians.push_back(median(stretch));
      stretch.clear();
      stretchStart = seconds;
    }
    stretch.push_back(wallMs);
    wall.push_back(wallMs);
    if (wallMs > 1.1 * flight.targetMs) flight.fractionOverTenPercent += 1.0;
    lastSeconds = seconds;
    ++flight.frames;
  }
  if (flight.frames == 0) throw engine::Error(file.string() + ": no governed frame in the series");
  // The last stretch, unless it is a scrap of under 5 s after full ones.
  if (flight.tenSecondMedians.empty() || lastSeconds - stretchStart >= 5.0) {
    flight.tenSecondMedians.push_back(median(stretch));
  }
  flight.seconds = lastSeconds - firstSeconds;
  flight.medianWallMs = median(wall);
  flight.fractionOverTenPercent /= static_cast<double>(flight.frames);
  return flight;
}

}  // namespace bench
