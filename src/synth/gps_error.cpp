#include "synth/gps_error.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"
#include "core/log.h"
#include "core/strings.h"
#include "synth/random.h"

namespace cls::synth {

GpsError parse_gps_error(const std::string& text) {
  GpsError e;
  e.enabled = true;
  if (trim_space(text) == "on") return e;
  const std::string usage = "--gps wants on, or h=METRES,v=METRES,datum=METRES,outliers=FRACTION,outlier-m=METRES "
                            "(any of them), got \"" + text + "\"";
  const auto items = key_numbers(text, usage);
  if (items.empty()) throw UsageError(usage);
  for (const auto& [key, x] : items) {
    if (key == "h" && x >= 0) e.horizontal = x;
    else if (key == "v" && x >= 0) e.vertical = x;
    else if (key == "datum") e.datum = x;
    else if (key == "outliers" && x >= 0 && x <= 1) e.outliers = x;
    else if (key == "outlier-m" && x >= 0) e.outlier_metres = x;
    else throw UsageError(usage + ": h, v, outlier-m must be >= 0, outliers in [0, 1], no other keys");
  }
  return e;
}

std::string gps_error_text(const GpsError& e) {
  if (!e.enabled) return "";
  return cat("h=", e.horizontal, ",v=", e.vertical, ",datum=", e.datum, ",outliers=", e.outliers, ",outlier-m=",
             e.outlier_metres);
}

std::vector<GpsFix> spoilt_gps(const std::vector<Vec3d>& centres, const GpsProjection& projection, const GpsError& e,
                               uint64_t seed) {
  Rng rng(seed, Stream::Gps);
  // Exactly round(outliers * n) photos are outliers, chosen by a seeded shuffle.
  std::vector<size_t> order(centres.size());
  std::iota(order.begin(), order.end(), 0);
  for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[static_cast<size_t>(rng.below(static_cast<int>(i)))]);
  const size_t outliers = static_cast<size_t>(std::llround(e.outliers * static_cast<double>(centres.size())));
  std::vector<bool> outlier(centres.size(), false);
  for (size_t i = 0; i < outliers; ++i) outlier[order[i]] = true;

  std::vector<GpsFix> fixes;
  for (size_t i = 0; i < centres.size(); ++i) {
    double x = centres[i].x + e.horizontal * rng.gaussian(), y = centres[i].y + e.horizontal * rng.gaussian();
    const double height = centres[i].z + e.datum + e.vertical * rng.gaussian();
    const double direction = rng.uniform(0, 2 * M_PI);
    if (outlier[i]) x += e.outlier_metres * std::cos(direction), y += e.outlier_metres * std::sin(direction);
    const std::array<double, 2> ll = projection.unproject(x, y);
    GpsFix fix;
    fix.latitude = ll[0];
    fix.longitude = ll[1];
    fix.altitude = height;
    fix.map_datum = "WGS-84";
    fixes.push_back(fix);
  }
  return fixes;
}

}  // namespace cls::synth
