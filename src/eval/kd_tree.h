#pragma once
// A static 3D k-d tree for nearest-neighbour queries within a radius (the 3D evaluation matches ground-
// truth points to Gaussian centres; the GT projection estimates the cloud's point spacing).
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace cls {

struct NearestHit {
  int64_t index = -1;   // into the points the tree was built on; -1 = nothing within the radius
  double distance = 0;  // Euclidean
};

class KdTree {
 public:
  explicit KdTree(std::vector<Vec3d> points);
  size_t size() const { return points_.size(); }
  // The nearest point with distance <= radius (ties: the lower index), skipping index `exclude`.
  NearestHit nearest(const Vec3d& query, double radius, int64_t exclude = -1) const;

 private:
  struct Node {
    int32_t begin = 0, end = 0;  // range in order_ (leaf) or the split point's position (inner)
    int32_t left = -1, right = -1;
    int axis = -1;               // -1 = leaf
    double split = 0;
  };
  int32_t build(int32_t begin, int32_t end);
  void search(int32_t node, const Vec3d& q, int64_t exclude, NearestHit& best, double& best_d2) const;

  std::vector<Vec3d> points_;
  std::vector<int32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace cls
