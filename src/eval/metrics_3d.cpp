#include "eval/metrics_3d.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "eval/kd_tree.h"

namespace cls {

PointMatching match_points(const std::vector<Vec3d>& gt_points, const std::vector<Vec3d>& centres, double radius) {
  PointMatching m;
  m.match.assign(gt_points.size(), -1);
  m.distance.assign(gt_points.size(), 0);
  const KdTree tree(centres);
  double sum = 0;
#pragma omp parallel for schedule(static) reduction(+ : sum)
  for (int64_t i = 0; i < int64_t(gt_points.size()); ++i) {
    const NearestHit hit = tree.nearest(gt_points[i], radius);
    m.match[i] = hit.index;
    if (hit.index >= 0) {
      m.distance[i] = hit.distance;
      sum += hit.distance;
    }
  }
  for (int64_t j : m.match) m.matched += j >= 0;
  m.coverage = gt_points.empty() ? 0 : double(m.matched) / double(gt_points.size());
  m.mean_distance = m.matched > 0 ? sum / double(m.matched) : 0;
  return m;
}

GtMatching match_gt(const std::vector<Vec3d>& gt_points, const std::vector<int32_t>& gt_labels,
                    const std::vector<Vec3d>& centres, double radius) {
  if (gt_points.size() != gt_labels.size()) throw std::invalid_argument("match_gt: GT points and labels differ in size");
  GtMatching g;
  g.num_centres = centres.size();
  std::vector<Vec3d> evaluated;
  for (size_t i = 0; i < gt_points.size(); ++i)
    if (gt_labels[i] >= 0) {
      evaluated.push_back(gt_points[i]);
      g.labels.push_back(gt_labels[i]);
    }
  g.matching = match_points(evaluated, centres, radius);
  return g;
}

Scores3d score_matched(const GtMatching& g, const std::vector<int32_t>& centre_labels, int num_classes) {
  if (g.num_centres != centre_labels.size()) throw std::invalid_argument("score_3d: centres and labels differ in size");
  const PointMatching& m = g.matching;
  Scores3d s{SegmentationScores{}, ConfusionMatrix(num_classes)};
  for (size_t i = 0; i < g.labels.size(); ++i)
    if (m.match[i] >= 0) s.confusion.add(g.labels[i], centre_labels[m.match[i]]);
  s.scores = segmentation_scores(s.confusion);
  s.gt_points = int64_t(g.labels.size());
  s.matched = m.matched;
  s.coverage = m.coverage;
  s.mean_distance = m.mean_distance;
  return s;
}

Scores3d score_3d(const std::vector<Vec3d>& gt_points, const std::vector<int32_t>& gt_labels,
                  const std::vector<Vec3d>& centres, const std::vector<int32_t>& centre_labels, int num_classes,
                  double radius) {
  if (centres.size() != centre_labels.size()) throw std::invalid_argument("score_3d: centres and labels differ in size");
  return score_matched(match_gt(gt_points, gt_labels, centres, radius), centre_labels, num_classes);
}

namespace {

// The matched GT points per centre and class: votes[c * K + k], K = max(num_classes, 1).
std::vector<int64_t> centre_votes(const GtMatching& g, int num_classes, const char* caller) {
  const size_t K = size_t(std::max(num_classes, 1));
  std::vector<int64_t> votes(g.num_centres * K, 0);
  for (size_t i = 0; i < g.labels.size(); ++i) {
    if (g.labels[i] < 0 || g.labels[i] >= num_classes)
      throw std::invalid_argument(std::string(caller) + ": a GT label is not in [0, num_classes)");
    if (g.matching.match[i] >= 0) ++votes[size_t(g.matching.match[i]) * K + size_t(g.labels[i])];
  }
  return votes;
}

}  // namespace

std::vector<int32_t> best_centre_labels(const GtMatching& g, int num_classes) {
  const size_t K = size_t(std::max(num_classes, 1));
  const std::vector<int64_t> votes = centre_votes(g, num_classes, "best_centre_labels");
  std::vector<int32_t> out(g.num_centres, 0);
  for (size_t c = 0; c < g.num_centres; ++c) {
    const int64_t* v = votes.data() + c * K;
    out[c] = int32_t(std::max_element(v, v + K) - v);  // the first maximum: ties go to the lower class
  }
  return out;
}

std::vector<int64_t> centres_per_class(const GtMatching& g, int num_classes) {
  const size_t K = size_t(std::max(num_classes, 1));
  const std::vector<int64_t> votes = centre_votes(g, num_classes, "centres_per_class");
  std::vector<int64_t> out(size_t(std::max(num_classes, 0)), 0);
  for (size_t c = 0; c < g.num_centres; ++c)
    for (size_t k = 0; k < out.size(); ++k) out[k] += votes[c * K + k] > 0;
  return out;
}

std::vector<int32_t> best_centre_labels(const std::vector<Vec3d>& gt_points, const std::vector<int32_t>& gt_labels,
                                        const std::vector<Vec3d>& centres, int num_classes, double radius) {
  return best_centre_labels(match_gt(gt_points, gt_labels, centres, radius), num_classes);
}

}  // namespace cls
