#include "eval/metrics_3d.h"

#include <algorithm>
#include <stdexcept>

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

Scores3d score_3d(const std::vector<Vec3d>& gt_points, const std::vector<int32_t>& gt_labels,
                  const std::vector<Vec3d>& centres, const std::vector<int32_t>& centre_labels, int num_classes,
                  double radius) {
  if (gt_points.size() != gt_labels.size()) throw std::invalid_argument("score_3d: GT points and labels differ in size");
  if (centres.size() != centre_labels.size()) throw std::invalid_argument("score_3d: centres and labels differ in size");
  std::vector<Vec3d> evaluated;
  std::vector<int32_t> labels;
  for (size_t i = 0; i < gt_points.size(); ++i)
    if (gt_labels[i] >= 0) {
      evaluated.push_back(gt_points[i]);
      labels.push_back(gt_labels[i]);
    }
  const PointMatching m = match_points(evaluated, centres, radius);
  Scores3d s{SegmentationScores{}, ConfusionMatrix(num_classes)};
  for (size_t i = 0; i < evaluated.size(); ++i)
    if (m.match[i] >= 0) s.confusion.add(labels[i], centre_labels[m.match[i]]);
  s.scores = segmentation_scores(s.confusion);
  s.gt_points = int64_t(evaluated.size());
  s.matched = m.matched;
  s.coverage = m.coverage;
  s.mean_distance = m.mean_distance;
  return s;
}

std::vector<int32_t> best_centre_labels(const std::vector<Vec3d>& gt_points, const std::vector<int32_t>& gt_labels,
                                        const std::vector<Vec3d>& centres, int num_classes, double radius) {
  if (gt_points.size() != gt_labels.size())
    throw std::invalid_argument("best_centre_labels: GT points and labels differ in size");
  std::vector<Vec3d> evaluated;
  std::vector<int32_t> labels;
  for (size_t i = 0; i < gt_points.size(); ++i)
    if (gt_labels[i] >= 0) {
      if (gt_labels[i] >= num_classes) throw std::invalid_argument("best_centre_labels: a GT label is not below num_classes");
      evaluated.push_back(gt_points[i]);
      labels.push_back(gt_labels[i]);
    }
  const PointMatching m = match_points(evaluated, centres, radius);
  const size_t K = size_t(std::max(num_classes, 1));
  std::vector<int64_t> votes(centres.size() * K, 0);
  for (size_t i = 0; i < evaluated.size(); ++i)
    if (m.match[i] >= 0) ++votes[size_t(m.match[i]) * K + size_t(labels[i])];
  std::vector<int32_t> out(centres.size(), 0);
  for (size_t c = 0; c < centres.size(); ++c) {
    const int64_t* v = votes.data() + c * K;
    out[c] = int32_t(std::max_element(v, v + K) - v);  // the first maximum: ties go to the lower class
  }
  return out;
}

}  // namespace cls
