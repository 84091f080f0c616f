#include "report/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>

#include "report/html.h"

namespace cls {
namespace {

// Tableau 10: distinguishable, and readable for the common colour-vision deficiencies.
const char* const kColours[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};

constexpr double kLeft = 60, kRight = 14, kTop = 46, kBottom = 40;  // plot margins

// 1, 2, 5 or 10 x 10^k nearest to (round) or at least (ceiling) x > 0.
double nice_number(double x, bool round) {
  const double e = std::floor(std::log10(x)), f = x / std::pow(10.0, e);
  double n;
  if (round) n = f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10;
  else n = f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10;
  return n * std::pow(10.0, e);
}

// A tick label: decimals from the tick step; thousands and millions shortened (12k, 1.5M).
std::string tick_label(double v, double step) {
  const double big = std::max(std::abs(v), std::abs(step));
  double scale = 1;
  const char* suffix = "";
  if (big >= 1e6) scale = 1e6, suffix = "M";
  else if (big >= 1e4) scale = 1e3, suffix = "k";
  const double s = step / scale;
  const int decimals = s >= 1 ? 0 : std::min(6, int(std::ceil(-std::log10(s) - 1e-9)));
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f%s", decimals, v / scale, suffix);
  return std::string(buf) == "-0" ? "0" : buf;
}

std::string log_tick_label(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int count) {
  if (hi < lo) std::swap(lo, hi);
  if (hi == lo) {  // one value: a range around it
    const double pad = lo == 0 ? 1 : 0.1 * std::abs(lo);
    lo -= pad, hi += pad;
  }
  const double step = nice_number(nice_number(hi - lo, false) / std::max(1, count), true);
  const double first = std::floor(lo / step);
  std::vector<double> ticks;
  for (int i = 0; ticks.empty() || ticks.back() < hi - 1e-9 * step; ++i) ticks.push_back((first + i) * step);
  return ticks;
}

std::vector<double> log_ticks(double lo, double hi) {
  const int e0 = int(std::floor(std::log10(lo) + 1e-9)), e1 = int(std::ceil(std::log10(hi) - 1e-9));
  std::vector<double> ticks;
  const bool fine = e1 - e0 <= 1;  // a decade or less: 1-2-5 steps, else powers of ten only
  for (int e = e0; e <= std::max(e1, e0 + 1); ++e) {
    const double p = std::pow(10.0, e);
    for (const double m : {1.0, 2.0, 5.0}) {
      if (m != 1 && !fine) continue;
      ticks.push_back(m * p);
    }
  }
  // Keep from the last tick <= lo to the first tick >= hi.
  while (ticks.size() > 2 && ticks[1] <= lo) ticks.erase(ticks.begin());
  while (ticks.size() > 2 && ticks[ticks.size() - 2] >= hi) ticks.pop_back();
  return ticks;
}

std::string svg_line_chart(const std::vector<ChartSeries>& series, const ChartOptions& o) {
  auto drawable = [&](double x, double y) { return std::isfinite(x) && std::isfinite(y) && (!o.log_y || y > 0); };
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const ChartSeries& s : series)
    for (const auto& [x, y] : s.points)
      if (drawable(x, y)) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);

  const double W = o.width, H = o.height, pw = W - kLeft - kRight, ph = H - kTop - kBottom;
  std::ostringstream svg;
  svg << "<svg class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << o.width << " " << o.height
      << "\" width=\"" << o.width << "\" height=\"" << o.height << "\" role=\"img\" aria-label=\""
      << html_escape(o.title) << "\">\n<title>" << html_escape(o.title) << "</title>\n";
  svg << "<text x=\"" << kLeft << "\" y=\"16\" class=\"chart-title\">" << html_escape(o.title) << "</text>\n";
  // Legend: one row under the title.
  double lx = kLeft;
  for (size_t i = 0; i < series.size(); ++i) {
    const char* colour = kColours[i % std::size(kColours)];
    svg << "<rect x=\"" << num(lx) << "\" y=\"26\" width=\"14\" height=\"4\" fill=\"" << colour << "\"/>"
        << "<text x=\"" << num(lx + 18) << "\" y=\"32\" class=\"chart-legend\">" << html_escape(series[i].name)
        << "</text>\n";
    lx += 30 + 6.5 * double(series[i].name.size());
  }
  svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << num(pw) << "\" height=\"" << num(ph)
      << "\" class=\"chart-frame\"/>\n";
  if (x0 > x1) {
    svg << "<text x=\"" << num(kLeft + pw / 2) << "\" y=\"" << num(kTop + ph / 2)
        << "\" text-anchor=\"middle\" class=\"chart-empty\">no data</text>\n</svg>";
    return svg.str();
  }

  const std::vector<double> xt = nice_ticks(x0, x1, 5);
  const std::vector<double> yt = o.log_y ? log_ticks(y0, y1) : nice_ticks(y0, y1, 4);
  auto fy = [&](double y) { return o.log_y ? std::log10(y) : y; };
  const double ax0 = xt.front(), ax1 = xt.back(), ay0 = fy(yt.front()), ay1 = fy(yt.back());
  auto px = [&](double x) { return kLeft + (x - ax0) / (ax1 - ax0) * pw; };
  auto py = [&](double y) { return kTop + ph - (fy(y) - ay0) / (ay1 - ay0) * ph; };

  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1, ystep = yt.size() > 1 ? yt[1] - yt[0] : 1;
  for (const double t : xt) {
    svg << "<line x1=\"" << num(px(t)) << "\" x2=\"" << num(px(t)) << "\" y1=\"" << kTop << "\" y2=\""
        << num(kTop + ph) << "\" class=\"chart-grid\"/><text x=\"" << num(px(t)) << "\" y=\"" << num(kTop + ph + 14)
        << "\" text-anchor=\"middle\" class=\"chart-tick\">" << tick_label(t, xstep) << "</text>\n";
  }
  for (const double t : yt) {
    svg << "<line x1=\"" << kLeft << "\" x2=\"" << num(kLeft + pw) << "\" y1=\"" << num(py(t)) << "\" y2=\""
        << num(py(t)) << "\" class=\"chart-grid\"/><text x=\"" << num(kLeft - 5) << "\" y=\"" << num(py(t) + 4)
        << "\" text-anchor=\"end\" class=\"chart-tick\">" << (o.log_y ? log_tick_label(t) : tick_label(t, ystep))
        << "</text>\n";
  }
  svg << "<text x=\"" << num(kLeft + pw / 2) << "\" y=\"" << num(H - 6) << "\" text-anchor=\"middle\" class=\"chart-axis\">"
      << html_escape(o.x_label) << "</text>\n";
  svg << "<text transform=\"translate(13 " << num(kTop + ph / 2) << ") rotate(-90)\" text-anchor=\"middle\" "
      << "class=\"chart-axis\">" << html_escape(o.y_label) << "</text>\n";

  for (size_t i = 0; i < series.size(); ++i) {
    const char* colour = kColours[i % std::size(kColours)];
    std::string run;  // the points of one unbroken stretch
    auto flush = [&] {
      if (run.empty()) return;
      svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.5\" points=\"" << run << "\"/>\n";
      run.clear();
    };
    for (const auto& [x, y] : series[i].points) {
      if (!drawable(x, y)) {
        flush();
        continue;
      }
      run += (run.empty() ? "" : " ") + num(px(x)) + "," + num(py(y));
      if (series[i].markers || series[i].points.size() == 1)
        svg << "<circle cx=\"" << num(px(x)) << "\" cy=\"" << num(py(y)) << "\" r=\"2.5\" fill=\"" << colour << "\"/>\n";
    }
    flush();
  }
  svg << "</svg>";
  return svg.str();
}

}  // namespace cls
