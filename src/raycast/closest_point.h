#pragma once
// Distances from points to a triangle mesh: an Embree BVH searched with point queries.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/math.h"

namespace cls {

// The point of triangle (a, b, c) closest to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3d closest_point_on_triangle(Vec3d p, Vec3d a, Vec3d b, Vec3d c);

class ClosestPointQuery {
 public:
  // cls::Error for out-of-range indices or non-finite vertices.
  ClosestPointQuery(const std::vector<Vec3f>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles);
  ~ClosestPointQuery();
  ClosestPointQuery(const ClosestPointQuery&) = delete;
  ClosestPointQuery& operator=(const ClosestPointQuery&) = delete;

  // Euclidean distance from p to the nearest triangle (+inf for an empty mesh). Thread-safe.
  double distance(Vec3d p) const;
  // distance() of every point, multithreaded.
  std::vector<double> distances(const std::vector<Vec3d>& points) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cls
