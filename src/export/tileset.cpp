#include "export/tileset.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/log.h"

namespace cls {

std::array<double, 16> ecef_tile_transform(const CrsToGeocentric& to_ecef, const Vec3d& origin) {
  auto ecef = [&](const Vec3d& p) {
    const auto xyz = to_ecef(p.x, p.y, p.z);
    if (!xyz) throw Error(cat("export: PROJ cannot place (", p.x, ", ", p.y, ", ", p.z, ") of the city model's CRS on the globe"));
    return Vec3d{(*xyz)[0], (*xyz)[1], (*xyz)[2]};
  };
  constexpr double h = 10;
  std::array<double, 16> m{};
  for (int axis = 0; axis < 3; ++axis) {
    Vec3d step{0, 0, 0};
    step[axis] = h;
    const Vec3d column = (1 / (2 * h)) * (ecef(origin + step) - ecef(origin - step));
    for (int r = 0; r < 3; ++r) m[4 * axis + r] = column[r];
  }
  const Vec3d centre = ecef(origin);
  for (int r = 0; r < 3; ++r) m[12 + r] = centre[r];
  m[15] = 1;
  return m;
}

std::array<double, 12> bounding_box(const std::vector<Vec3d>& points, const std::vector<double>& radii) {
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < points.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], points[i][a] - radii[i]);
      hi[a] = std::max(hi[a], points[i][a] + radii[i]);
    }
  std::array<double, 12> box{};
  for (int a = 0; a < 3; ++a) {
    box[a] = (lo[a] + hi[a]) / 2;
    box[3 + 4 * a] = (hi[a] - lo[a]) / 2;  // half-axis a along axis a
  }
  return box;
}

nlohmann::json tileset_json(const std::array<double, 16>& transform, const std::array<double, 12>& box,
                            const std::string& content_uri, const nlohmann::json& extras) {
  const double diagonal = 2 * std::sqrt(box[3] * box[3] + box[7] * box[7] + box[11] * box[11]);
  nlohmann::json tileset{{"asset", {{"version", "1.1"}, {"generator", "citylangsplat " CLS_VERSION}}},
                         {"geometricError", diagonal},
                         {"root",
                          {{"transform", transform},
                           {"boundingVolume", {{"box", box}}},
                           {"geometricError", 0},
                           {"refine", "ADD"},
                           {"content", {{"uri", content_uri}}}}}};
  if (!extras.empty()) tileset["asset"]["extras"] = extras;
  return tileset;
}

}  // namespace cls
