#pragma once
// Brute-force reference for the raycaster: every ray against every triangle in double precision
// (Moller-Trumbore), with the tie rule of raycaster.h written out directly.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raycast/pixel_ray.h"
#include "raycast/raycaster.h"

namespace cls::test {

struct OracleHit {
  double depth = 0;
  uint32_t prim = kNoHit;
};

// Ray parameter of the hit of (o, d) with triangle (a, b, c), or -1 if none (t must be >= tnear).
inline double moller_trumbore(Vec3d o, Vec3d d, Vec3d a, Vec3d b, Vec3d c, double tnear) {
  const Vec3d e1 = b - a, e2 = c - a;
  const Vec3d p = cross(d, e2);
  const double det = dot(e1, p);
  if (std::abs(det) < 1e-300) return -1;
  const double inv = 1.0 / det;
  const Vec3d s = o - a;
  const double u = dot(s, p) * inv;
  if (u < 0 || u > 1) return -1;
  const Vec3d q = cross(s, e1);
  const double v = dot(d, q) * inv;
  if (v < 0 || u + v > 1) return -1;
  const double t = dot(e2, q) * inv;
  return t >= tnear ? t : -1;
}

// The closest hit t0; among hits within 1e-4 t0 + 1e-5 of it, the highest priority, then the closest.
inline OracleHit oracle_cast(const std::vector<Vec3f>& vertices, const std::vector<std::array<uint32_t, 3>>& tris,
                             const std::vector<uint8_t>& priority, Vec3d o, Vec3d d, double tnear = 0) {
  std::vector<std::pair<double, uint32_t>> hits;
  double t0 = INFINITY;
  for (uint32_t k = 0; k < tris.size(); ++k) {
    const double t = moller_trumbore(o, d, cast<double>(vertices[tris[k][0]]), cast<double>(vertices[tris[k][1]]),
                                     cast<double>(vertices[tris[k][2]]), tnear);
    if (t < 0) continue;
    hits.push_back({t, k});
    t0 = std::min(t0, t);
  }
  OracleHit best;
  int best_priority = -1;
  for (const auto& [t, k] : hits) {
    if (t > t0 + 1e-4 * t0 + 1e-5) continue;
    const int p = priority.empty() ? 0 : priority[k];
    if (p > best_priority || (p == best_priority && t < best.depth)) {
      best = {t, k};
      best_priority = p;
    }
  }
  return best;
}

inline std::vector<OracleHit> oracle_view(const std::vector<Vec3f>& vertices,
                                          const std::vector<std::array<uint32_t, 3>>& tris,
                                          const std::vector<uint8_t>& priority, const PinholeCamera& cam,
                                          const Pose& pose) {
  std::vector<OracleHit> out(static_cast<size_t>(cam.width) * cam.height);
  const Vec3d o = pose.center();
#pragma omp parallel for schedule(dynamic, 4)
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      const Vec3d d = camera_to_world_dir(pose.R, pixel_ray_camera(cam.fx, cam.fy, cam.cx, cam.cy, i, j));
      out[static_cast<size_t>(j) * cam.width + i] = oracle_cast(vertices, tris, priority, o, d);
    }
  return out;
}

}  // namespace cls::test
