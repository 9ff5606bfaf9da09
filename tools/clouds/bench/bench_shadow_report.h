#pragma once
// The cloud shadow map's part of the benchmark's outputs (bench_shadow.h): its CSV rows, its
// Markdown section and its plot of error against time.
#include <nlohmann/json.hpp>
#include <ostream>

#include "bench_shadow.h"

namespace bench {

// Rows of results.csv's columns: view "shadow map: <view>", GPU time the mean per frame over
// a cycle of turns (min: none, max: the frame after a cut), PSNR and errors of the ground's
// transmittance.
void writeShadowCsv(std::ostream& out, const ShadowResults& shadows);
void writeShadowMarkdown(std::ostream& out, const ShadowResults& shadows);
// One plot (plots.json's format): GPU ms per frame against transmittance PSNR, per sweep and
// for the presets, averaged over the views.
nlohmann::json shadowPlot(const ShadowResults& shadows, const char* png);

}  // namespace bench
