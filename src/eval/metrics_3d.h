#pragma once
// The paper's 3D evaluation (section 4.1, Table 2): ground-truth points matched to the nearest Gaussian
// centre within a radius (k-d tree); scores over the matched points.
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "eval/metrics_2d.h"

namespace cls {

struct PointMatching {
  std::vector<int64_t> match;     // per GT point: index of the nearest centre within the radius, -1 = none
  std::vector<double> distance;   // per GT point: distance to it (0 where unmatched)
  int64_t matched = 0;
  double coverage = 0;            // matched / GT points (0 for no GT points)
  double mean_distance = 0;       // over the matched points
};

PointMatching match_points(const std::vector<Vec3d>& gt_points, const std::vector<Vec3d>& centres, double radius);

struct Scores3d {
  SegmentationScores scores;  // over matched GT points (mIoU, wIoU, accuracy)
  ConfusionMatrix confusion;
  int64_t gt_points = 0, matched = 0;
  double coverage = 0, mean_distance = 0;
};

// The GT points with a label >= 0 matched once to the centres, so that several labellings of the same
// centres are scored without matching again.
struct GtMatching {
  std::vector<int32_t> labels;  // per evaluated GT point (gt_labels >= 0), in order
  PointMatching matching;       // per evaluated GT point
  size_t num_centres = 0;
};
GtMatching match_gt(const std::vector<Vec3d>& gt_points, const std::vector<int32_t>& gt_labels,
                    const std::vector<Vec3d>& centres, double radius);
// score_3d of a matching: centre_labels per centre, in [0, K).
Scores3d score_matched(const GtMatching& matching, const std::vector<int32_t>& centre_labels, int num_classes);

// gt_labels: per GT point, class index in [0, K) or -1 (not evaluated: such points are left out entirely,
// from the coverage too); centre_labels: per centre, class index in [0, K).
Scores3d score_3d(const std::vector<Vec3d>& gt_points, const std::vector<int32_t>& gt_labels,
                  const std::vector<Vec3d>& centres, const std::vector<int32_t>& centre_labels, int num_classes,
                  double radius);

// The labelling of the centres that gets the most matched GT points right: each centre takes the majority
// class of the GT points matched to it (ties: the lower class; a centre no GT point matches gets 0). Its
// accuracy is the most any field on these centres can reach under this matching (its mIoU is not a
// strict bound, but close). Arguments as for score_3d.
std::vector<int32_t> best_centre_labels(const GtMatching& matching, int num_classes);
std::vector<int32_t> best_centre_labels(const std::vector<Vec3d>& gt_points, const std::vector<int32_t>& gt_labels,
                                        const std::vector<Vec3d>& centres, int num_classes, double radius);

// Per class: how many distinct centres its matched GT points are matched to. A class held by a handful
// of Gaussians gets a 3D score that moves by many points when one of them changes its label.
std::vector<int64_t> centres_per_class(const GtMatching& matching, int num_classes);

}  // namespace cls
