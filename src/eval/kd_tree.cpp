#include "eval/kd_tree.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace cls {
namespace {
constexpr int32_t kLeafSize = 8;
}

KdTree::KdTree(std::vector<Vec3d> points) : points_(std::move(points)) {
  order_.resize(points_.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (!points_.empty()) build(0, int32_t(points_.size()));
}

int32_t KdTree::build(int32_t begin, int32_t end) {
  const int32_t id = int32_t(nodes_.size());
  nodes_.push_back({begin, end, -1, -1, -1, 0});
  if (end - begin <= kLeafSize) return id;
  // Split along the widest extent at the median.
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (int32_t i = begin; i < end; ++i)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], points_[order_[i]][a]);
      hi[a] = std::max(hi[a], points_[order_[i]][a]);
    }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
  const int32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int32_t a, int32_t b) { return points_[a][axis] < points_[b][axis]; });
  const double split = points_[order_[mid]][axis];
  const int32_t left = build(begin, mid);
  const int32_t right = build(mid, end);
  Node& n = nodes_[id];
  n.axis = axis;
  n.split = split;
  n.left = left;
  n.right = right;
  return id;
}

void KdTree::search(int32_t id, const Vec3d& q, int64_t exclude, NearestHit& best, double& best_d2) const {
  const Node& n = nodes_[id];
  if (n.axis < 0) {
    for (int32_t i = n.begin; i < n.end; ++i) {
      const int32_t p = order_[i];
      if (p == exclude) continue;
      const Vec3d d = points_[p] - q;
      const double d2 = dot(d, d);
      if (d2 < best_d2 || (d2 == best_d2 && best.index >= 0 && p < best.index)) {
        best_d2 = d2;
        best.index = p;
      }
    }
    return;
  }
  // Left holds coordinates <= split, right >= split (equal values may sit on both sides).
  const double diff = q[n.axis] - n.split;
  const int32_t first = diff <= 0 ? n.left : n.right;
  const int32_t second = diff <= 0 ? n.right : n.left;
  search(first, q, exclude, best, best_d2);
  if (diff * diff <= best_d2) search(second, q, exclude, best, best_d2);
}

NearestHit KdTree::nearest(const Vec3d& query, double radius, int64_t exclude) const {
  NearestHit best;
  if (points_.empty() || !(radius >= 0)) return best;
  double best_d2 = radius * radius;
  // Points exactly at the radius count: start the bound just above it.
  best_d2 = std::nextafter(best_d2, std::numeric_limits<double>::infinity());
  search(0, query, exclude, best, best_d2);
  if (best.index >= 0) best.distance = std::sqrt(best_d2);
  return best;
}

}  // namespace cls
