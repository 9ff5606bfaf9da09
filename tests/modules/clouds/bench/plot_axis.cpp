#include "plot_axis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace bench {

namespace {

constexpr double kLinearMarginFraction = 0.05;  // of the data span, on each side
constexpr double kMinLogMarginDecades = 0.05;   // keeps markers off the frame on short spans
constexpr double kLogMarginFraction = 0.03;     // of the data span in decades, on each side
constexpr std::size_t kMaxTicks = 1000;         // guards degenerate ranges, never reached in use

PlotAxis defaultAxis(bool log) {
  return log ? PlotAxis{1.0, 1000.0, true} : PlotAxis{0.0, 1.0, false};
}

PlotAxis fitLinear(double lo, double hi) {
  const double span = hi - lo;
  // A single value still needs a range: pad by a tenth of its magnitude (or 1 around zero).
  const double pad =
      span > 0.0 ? kLinearMarginFraction * span : (lo != 0.0 ? 0.1 * std::abs(lo) : 1.0);
  return PlotAxis{lo - pad, hi + pad, false};
}

PlotAxis fitLog(double lo, double hi) {
  const double loDecades = std::log10(lo);
  const double hiDecades = std::log10(hi);
  const double margin =
      std::max(kMinLogMarginDecades, kLogMarginFraction * (hiDecades - loDecades));
  // Half-decade steps in log space: 10^k and 10^(k + 0.5) ~ 3.16 x 10^k.
  const double startDecades = std::floor(2.0 * (loDecades - margin)) / 2.0;
  const double endDecades = std::ceil(2.0 * (hiDecades + margin)) / 2.0;
  return PlotAxis{std::pow(10.0, startDecades), std::pow(10.0, endDecades), true};
}

bool isUsable(const PlotAxis& axis) {
  return std::isfinite(axis.min) && std::isfinite(axis.max) && axis.max > axis.min &&
         (!axis.log || axis.min > 0.0);
}

// The smallest 1, 2 or 5 x 10^n step that divides `span` into at most `maxIntervals`.
double niceStep(double span, double maxIntervals) {
  const double rawStep = span / maxIntervals;
  const double magnitude = std::pow(10.0, std::floor(std::log10(rawStep)));
  for (const double multiple : {1.0, 2.0, 5.0}) {
    if (multiple * magnitude >= rawStep * (1.0 - 1e-9)) return multiple * magnitude;
  }
  return 10.0 * magnitude;
}

// Digits after the point needed to print multiples of `step` exactly (step = m x 10^n).
int decimalsFor(double step) {
  return std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
}

std::vector<AxisTick> linearTicks(const PlotAxis& axis, double lengthPx, double minLabelSpacingPx) {
  const double maxIntervals = std::max(1.0, std::floor(lengthPx / minLabelSpacingPx));
  const double step = niceStep(axis.max - axis.min, maxIntervals);
  const int decimals = decimalsFor(step);
  std::vector<AxisTick> ticks;
  // Ticks are index x step rather than an accumulated sum, so 0.1 + 0.2 errors never show.
  const double firstIndex = std::ceil(axis.min / step - 1e-9);
  const double lastIndex = std::floor(axis.max / step + 1e-9);
  for (double index = firstIndex; index <= lastIndex && ticks.size() < kMaxTicks; ++index) {
    const double value = index * step;
    ticks.push_back({value, true, formatTickValue(value, decimals)});
  }
  return ticks;
}

std::vector<AxisTick> logTicks(const PlotAxis& axis, double lengthPx, double minLabelSpacingPx) {
  const double startDecades = std::log10(axis.min);
  const double endDecades = std::log10(axis.max);
  const double pxPerDecade = lengthPx / (endDecades - startDecades);
  // The closest labelled ticks are 1 -> 2 and 5 -> 10, log10(2) ~ 0.3 decades apart.
  const bool labelMinor = std::log10(2.0) * pxPerDecade >= minLabelSpacingPx;
  const int labelEveryDecades =
      std::max(1, static_cast<int>(std::ceil(minLabelSpacingPx / std::max(pxPerDecade, 1e-9))));
  std::vector<AxisTick> ticks;
  const int firstDecade = static_cast<int>(std::floor(startDecades + 1e-9));
  const int lastDecade = static_cast<int>(std::ceil(endDecades - 1e-9));
  for (int decade = firstDecade; decade <= lastDecade && ticks.size() < kMaxTicks; ++decade) {
    const int decimals = std::max(0, -decade);
    for (const double multiple : {1.0, 2.0, 5.0}) {
      const double value = multiple * std::pow(10.0, decade);
      const double offsetDecades = std::log10(value);
      if (offsetDecades < startDecades - 1e-9 || offsetDecades > endDecades + 1e-9) continue;
      const bool major = multiple == 1.0;
      const bool labelled = major ? decade % labelEveryDecades == 0 : labelMinor;
      ticks.push_back({value, major, labelled ? formatTickValue(value, decimals) : ""});
    }
  }
  return ticks;
}

}  // namespace

bool PlotAxis::canShow(double value) const {
  return std::isfinite(value) && (!log || value > 0.0);
}

double PlotAxis::fraction(double value) const {
  if (!canShow(value)) return std::numeric_limits<double>::quiet_NaN();
  if (log) return (std::log10(value) - std::log10(min)) / (std::log10(max) - std::log10(min));
  return (value - min) / (max - min);
}

PlotAxis fitAxis(std::span<const double> values, bool log) {
  const PlotAxis probe{0.0, 1.0, log};
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  for (const double value : values) {
    if (!probe.canShow(value)) continue;
    lo = std::min(lo, value);
    hi = std::max(hi, value);
  }
  if (lo > hi) return defaultAxis(log);
  const PlotAxis fitted = log ? fitLog(lo, hi) : fitLinear(lo, hi);
  // Values near the limits of double (1e308) overflow the padded range; fall back rather than
  // draw a broken axis.
  return isUsable(fitted) ? fitted : defaultAxis(log);
}

std::vector<AxisTick> axisTicks(const PlotAxis& axis, double lengthPx, double minLabelSpacingPx) {
  if (!isUsable(axis) || !(lengthPx > 0.0) || !(minLabelSpacingPx > 0.0)) return {};
  return axis.log ? logTicks(axis, lengthPx, minLabelSpacingPx)
                  : linearTicks(axis, lengthPx, minLabelSpacingPx);
}

std::string formatTickValue(double value, int decimals) {
  if (value == 0.0 || !std::isfinite(value)) return value == 0.0 ? "0" : std::to_string(value);
  std::array<char, 64> text{};
  const double magnitude = std::abs(value);
  if (magnitude >= 1e6 || magnitude < 1e-4) {
    const int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    const double mantissa = value / std::pow(10.0, exponent);
    std::snprintf(text.data(), text.size(), "%.3ge%d", mantissa, exponent);
    return text.data();
  }
  std::snprintf(text.data(), text.size(), "%.*f", std::clamp(decimals, 0, 12), value);
  const std::string printed = text.data();
  // Rounding can turn -0.0001 into "-0.000"; a tick at zero reads as "0".
  if (printed.find_first_not_of("-0.") == std::string::npos) return "0";
  return printed;
}

}  // namespace bench
