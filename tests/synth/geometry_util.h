#pragma once
// Brute-force geometry for the synth tests: point-to-triangle distance (Ericson, Real-Time
// Collision Detection, 5.1.5) over every triangle.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/math.h"

namespace cls::test {

inline Vec3d closest_on_triangle(Vec3d p, Vec3d a, Vec3d b, Vec3d c) {
  const Vec3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3d bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3d cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + (vb * denom) * ab + (vc * denom) * ac;
}

// Distance from p to the nearest triangle and that triangle's index.
inline std::pair<double, size_t> nearest_triangle(Vec3d p, const std::vector<Vec3f>& vertices,
                                                  const std::vector<std::array<uint32_t, 3>>& triangles) {
  double best = INFINITY;
  size_t best_tri = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    const double d = norm(p - closest_on_triangle(p, cast<double>(vertices[tri[0]]), cast<double>(vertices[tri[1]]),
                                                  cast<double>(vertices[tri[2]])));
    if (d < best) best = d, best_tri = t;
  }
  return {best, best_tri};
}

}  // namespace cls::test
