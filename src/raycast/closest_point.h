#pragma once
// Distances from points to a triangle mesh: an Embree BVH searched with point queries.
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/math.h"

namespace cls {

// The point of triangle (a, b, c) closest to p (Ericson, Real-Time Collision Detection 5.1.5).
// `on_face`, if given, says whether it is inside the face (p projects into the triangle) rather than
// on an edge or corner.
Vec3d closest_point_on_triangle(Vec3d p, Vec3d a, Vec3d b, Vec3d c, bool* on_face = nullptr);

// The nearest point of a mesh to a query point.
struct MeshPoint {
  Vec3d point;
  Vec3d normal;           // unit normal of its triangle (winding order; zero for a degenerate one)
  uint32_t triangle = 0;  // index into the mesh's triangles
  bool on_face = false;   // inside the triangle, not on an edge or corner: p lies over the mesh, not beside it
  double distance = INFINITY;
};

class ClosestPointQuery {
 public:
  // cls::Error for out-of-range indices or non-finite vertices.
  ClosestPointQuery(const std::vector<Vec3f>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles);
  ~ClosestPointQuery();
  ClosestPointQuery(const ClosestPointQuery&) = delete;
  ClosestPointQuery& operator=(const ClosestPointQuery&) = delete;

  // The nearest point of the mesh to p (distance +inf for an empty mesh). Thread-safe.
  MeshPoint nearest(Vec3d p) const;
  // Euclidean distance from p to the nearest triangle (+inf for an empty mesh). Thread-safe.
  double distance(Vec3d p) const { return nearest(p).distance; }
  // distance() of every point, multithreaded.
  std::vector<double> distances(const std::vector<Vec3d>& points) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cls
