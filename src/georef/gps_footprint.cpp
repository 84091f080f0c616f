#include "georef/gps_footprint.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cls {

GpsFootprint gps_footprint(const std::vector<GpsFix>& fixes, const SemanticMesh& mesh, const GpsProjection& projection) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  GpsFootprint f;
  f.box = {kInf, kInf, -kInf, -kInf};
  f.model_heights = {kInf, -kInf};
  for (const auto& v : mesh.vertices) {
    const double x = v[0] + mesh.origin[0], y = v[1] + mesh.origin[1], z = v[2] + mesh.origin[2];
    f.box = {std::min(f.box[0], x), std::min(f.box[1], y), std::max(f.box[2], x), std::max(f.box[3], y)};
    f.model_heights = {std::min(f.model_heights[0], z), std::max(f.model_heights[1], z)};
  }
  std::vector<double> distances;
  for (const GpsFix& fix : fixes) {
    const std::array<double, 2> p = projection.project(fix.latitude, fix.longitude);
    const double dx = std::max({f.box[0] - p[0], 0.0, p[0] - f.box[2]});
    const double dy = std::max({f.box[1] - p[1], 0.0, p[1] - f.box[3]});
    distances.push_back(std::hypot(dx, dy));
  }
  f.fixes = distances.size();
  if (distances.empty()) return f;
  std::sort(distances.begin(), distances.end());
  const size_t n = distances.size();
  f.median_distance = n % 2 ? distances[n / 2] : 0.5 * (distances[n / 2 - 1] + distances[n / 2]);
  f.max_distance = distances.back();
  return f;
}

}  // namespace cls
