#pragma once
// Brute-force geometry for the synth tests: point-to-triangle distance over every triangle
// (closest_point_on_triangle is checked against its own oracle in tests/raycast).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/math.h"
#include "raycast/closest_point.h"

namespace cls::test {

// Distance from p to the nearest triangle and that triangle's index.
inline std::pair<double, size_t> nearest_triangle(Vec3d p, const std::vector<Vec3f>& vertices,
                                                  const std::vector<std::array<uint32_t, 3>>& triangles) {
  double best = INFINITY;
  size_t best_tri = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    const double d = norm(p - closest_point_on_triangle(p, cast<double>(vertices[tri[0]]), cast<double>(vertices[tri[1]]),
                                                  cast<double>(vertices[tri[2]])));
    if (d < best) best = d, best_tri = t;
  }
  return {best, best_tri};
}

}  // namespace cls::test
