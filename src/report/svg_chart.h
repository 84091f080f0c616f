#pragma once
// Line charts as inline SVG (no script, no external file): several series, axes with "nice" ticks,
// an optional log-scale y axis (losses), a legend; every text escaped.
#include <string>
#include <utility>
#include <vector>

namespace cls {

struct ChartSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y); non-finite values (and y <= 0 on a log axis) are gaps
  bool markers = false;                           // dots at the points (sparse series, e.g. held-out PSNR)
};

struct ChartOptions {
  std::string title, x_label, y_label;
  bool log_y = false;
  int width = 400, height = 260;  // CSS pixels; the SVG scales with its container
};

// An <svg class="chart"> element; a chart without any drawable point says so in its plot area.
std::string svg_line_chart(const std::vector<ChartSeries>& series, const ChartOptions& options);

// Axis ticks covering [lo, hi] with about `count` steps of 1, 2 or 5 x 10^k: the first tick <= lo,
// the last >= hi. Equal ends are widened. Exposed for tests.
std::vector<double> nice_ticks(double lo, double hi, int count);

// Log-axis ticks (powers of ten; 1-2-5 within a decade or less) covering [lo, hi], 0 < lo <= hi.
std::vector<double> log_ticks(double lo, double hi);

}  // namespace cls
