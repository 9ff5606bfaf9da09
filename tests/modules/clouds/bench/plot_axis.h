#pragma once
// Axis ranges and ticks for the benchmark chart: pure functions, no drawing.
#include <span>
#include <string>
#include <vector>

namespace bench {

// One axis of a chart: its data range and scale.
struct PlotAxis {
  double min = 0.0;  // data value at the start (left or bottom); > 0 on a log axis
  double max = 1.0;  // data value at the end (right or top); > min
  bool log = false;  // log10 scale

  // Whether `value` can be placed on this axis at all: finite, and > 0 on a log axis.
  bool canShow(double value) const;
  // Where `value` falls along the axis: 0 at min, 1 at max, outside [0, 1] beyond the range;
  // NaN when !canShow(value).
  double fraction(double value) const;
};

// The range that fits `values` with a margin so that no point sits on the frame. Linear axes pad
// 5% of the span on each side; log axes pad a little and round out to whole or half decades
// (10^k or 10^(k+0.5)). Values the axis cannot show are skipped; when none are left the range is
// a default ([0, 1], or 1 to 1000 on a log axis).
PlotAxis fitAxis(std::span<const double> values, bool log);

struct AxisTick {
  double value = 0.0;
  bool major = true;  // decades on log axes, every tick on linear axes (stronger grid line)
  std::string label;  // empty when the tick is drawn unlabelled
};

// The ticks inside the axis range, for an axis `lengthPx` long whose labels need at least
// `minLabelSpacingPx` between their anchors. Linear axes step by 1, 2 or 5 x 10^n, as finely as
// the spacing allows. Log axes tick every decade (labelling every n-th when decades are short)
// and put unlabelled minor ticks at 2 and 5 x 10^k, labelled when a decade is long enough.
std::vector<AxisTick> axisTicks(const PlotAxis& axis, double lengthPx, double minLabelSpacingPx);

// `value` with `decimals` digits after the point ("0.5", "20", "1000"); very large or small
// magnitudes switch to a short exponent form ("2e6", "1e-5"). Never prints "-0".
std::string formatTickValue(double value, int decimals);

}  // namespace bench
