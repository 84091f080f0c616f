// Metrics against hand-computed confusion matrices, and the k-d tree against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "eval/kd_tree.h"
#include "eval/metrics_2d.h"
#include "eval/metrics_3d.h"

using namespace cls;

namespace {

// K = 4: 0 wall, 1 window, 2 door (neither in GT nor predicted), 3 roof (predicted, absent from GT).
//          pred 0  1  2  3
//   gt 0       6  2  0  1     GT_0 = 9
//   gt 1       1  3  0  0     GT_1 = 4
//   gt 2, 3    0  0  0  0
//   P:         7  5  0  1
ConfusionMatrix hand_matrix() {
  ConfusionMatrix m(4);
  m.add(0, 0, 6);
  m.add(0, 1, 2);
  m.add(0, 3, 1);
  m.add(1, 0, 1);
  m.add(1, 1, 3);
  return m;
}

}  // namespace

TEST(Metrics2d, HandComputedConfusionMatrixWithEmptyAndGtAbsentClasses) {
  const SegmentationScores s = segmentation_scores(hand_matrix());
  ASSERT_EQ(s.per_class.size(), 4u);
  EXPECT_DOUBLE_EQ(s.per_class[0].iou, 6.0 / 10.0);  // 6 / (9 + 7 - 6)
  EXPECT_DOUBLE_EQ(s.per_class[1].iou, 3.0 / 6.0);   // 3 / (4 + 5 - 3)
  EXPECT_FALSE(s.per_class[2].present);              // empty: not in the mean
  EXPECT_TRUE(s.per_class[3].present);               // predicted only: IoU 0, in the mean
  EXPECT_DOUBLE_EQ(s.per_class[3].iou, 0.0);
  EXPECT_EQ(s.classes_in_miou, 3);
  EXPECT_DOUBLE_EQ(s.miou, (0.6 + 0.5 + 0.0) / 3);
  EXPECT_DOUBLE_EQ(s.wiou, (9 * 0.6 + 4 * 0.5) / 13);
  EXPECT_DOUBLE_EQ(s.accuracy, 9.0 / 13);
  EXPECT_EQ(s.samples, 13);
  EXPECT_DOUBLE_EQ(s.per_class[0].precision, 6.0 / 7);
  EXPECT_DOUBLE_EQ(s.per_class[0].recall, 6.0 / 9);
  EXPECT_DOUBLE_EQ(s.per_class[1].precision, 3.0 / 5);
  EXPECT_DOUBLE_EQ(s.per_class[1].recall, 3.0 / 4);
  EXPECT_DOUBLE_EQ(s.per_class[3].precision, 0.0);
  EXPECT_DOUBLE_EQ(s.per_class[3].recall, 0.0);  // GT_3 = 0
}

TEST(Metrics2d, EmptyMatrixScoresZero) {
  const SegmentationScores s = segmentation_scores(ConfusionMatrix(3));
  EXPECT_EQ(s.classes_in_miou, 0);
  EXPECT_EQ(s.miou, 0.0);
  EXPECT_EQ(s.wiou, 0.0);
  EXPECT_EQ(s.accuracy, 0.0);
}

TEST(Metrics2d, MatricesAddUpAndRejectBadClasses) {
  ConfusionMatrix m = hand_matrix();
  m.add(hand_matrix());
  EXPECT_EQ(m.total(), 26);
  EXPECT_EQ(m.at(0, 1), 4);
  EXPECT_DOUBLE_EQ(segmentation_scores(m).miou, segmentation_scores(hand_matrix()).miou);
  EXPECT_THROW(m.add(4, 0), std::out_of_range);
  EXPECT_THROW(m.add(0, -1), std::out_of_range);
}

TEST(Metrics2d, ScoreLabelsSkipsInvalidGtAndIgnoredPredictions) {
  const ImageScoring r = score_labels({-1, 0, 1, 1, 0, 2}, {0, -1, 1, 0, 0, -1}, 3);
  EXPECT_EQ(r.pixels, 6);
  EXPECT_EQ(r.valid_gt, 5);
  EXPECT_EQ(r.scored, 3);
  EXPECT_EQ(r.confusion.at(1, 1), 1);
  EXPECT_EQ(r.confusion.at(1, 0), 1);
  EXPECT_EQ(r.confusion.at(0, 0), 1);
  EXPECT_EQ(r.confusion.total(), 3);
  EXPECT_EQ(r.confusion.ignored_count(0), 1);  // gt 0 at index 1, prediction ignored
  EXPECT_EQ(r.confusion.ignored_count(1), 0);
  EXPECT_EQ(r.confusion.ignored_count(2), 1);  // gt 2 at index 5
}

// A class whose every GT pixel a method leaves unpredicted (below the threshold, or outside a label
// map's coverage) stays in that method's mIoU with IoU 0: the GT, not the method, sets the class list.
TEST(Metrics2d, ClassOnlyInIgnoredPixelsCountsWithIouZero) {
  // GT: 0 0 1 1 2 2; prediction: 0 0 1 1 -1 -1 (class 2 never predicted).
  const ImageScoring r = score_labels({0, 0, 1, 1, 2, 2}, {0, 0, 1, 1, -1, -1}, 3);
  const SegmentationScores s = segmentation_scores(r.confusion);
  EXPECT_EQ(s.classes_in_miou, 3);
  EXPECT_TRUE(s.per_class[2].present);
  EXPECT_DOUBLE_EQ(s.per_class[2].iou, 0.0);
  EXPECT_EQ(s.per_class[2].ignored, 2);
  EXPECT_DOUBLE_EQ(s.miou, (1.0 + 1.0 + 0.0) / 3);
  EXPECT_DOUBLE_EQ(s.wiou, 1.0);      // weights are scored GT counts: class 2 has none
  EXPECT_DOUBLE_EQ(s.accuracy, 1.0);  // over scored pixels: ignored ones are not errors
  PerImageClassAverages avg(3);
  avg.add_image(r.confusion);
  EXPECT_EQ(avg.images_with(2), 1);
  EXPECT_DOUBLE_EQ(avg.mean(2).iou, 0.0);
  EXPECT_TRUE(avg.mean(2).present);
  ConfusionMatrix twice = r.confusion;
  twice.add(r.confusion);
  EXPECT_EQ(twice.ignored_count(2), 4);
  EXPECT_THROW(twice.add_ignored(3), std::out_of_range);
}

TEST(Metrics2d, PerClassAveragesOnlyOverImagesContainingTheClass) {
  PerImageClassAverages avg(3);
  ConfusionMatrix a(3);  // class 0 only: GT 4, P 2, TP 2 -> IoU 0.5, precision 1, recall 0.5
  a.add(0, 0, 2);
  a.add(0, 1, 2);       // class 1 predicted but not in a's GT: a does not count for class 1
  ConfusionMatrix b(3);  // class 0: GT 1, P 2, TP 1; class 1: GT 2, P 1, TP 1
  b.add(0, 0);
  b.add(1, 1);
  b.add(1, 0);
  avg.add_image(a);
  avg.add_image(b);
  EXPECT_EQ(avg.images_with(0), 2);
  EXPECT_EQ(avg.images_with(1), 1);
  EXPECT_EQ(avg.images_with(2), 0);
  EXPECT_DOUBLE_EQ(avg.mean(0).iou, (0.5 + 0.5) / 2);
  EXPECT_DOUBLE_EQ(avg.mean(0).precision, (1.0 + 0.5) / 2);
  EXPECT_DOUBLE_EQ(avg.mean(0).recall, (0.5 + 1.0) / 2);
  EXPECT_DOUBLE_EQ(avg.mean(1).iou, 0.5);
  EXPECT_DOUBLE_EQ(avg.mean(1).precision, 1.0);
  EXPECT_DOUBLE_EQ(avg.mean(1).recall, 0.5);
  EXPECT_FALSE(avg.mean(2).present);
}

TEST(KdTree, MatchesBruteForceOnRandomPoints) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3d> pts;
  for (int i = 0; i < 3000; ++i) pts.push_back({u(rng), u(rng), 0.3 * u(rng)});
  for (int i = 0; i < 50; ++i) pts.push_back(pts[i * 7]);  // duplicates: ties go to the lower index
  const KdTree tree(pts);
  for (double radius : {0.01, 0.05, 0.2, std::numeric_limits<double>::infinity()})
    for (int q = 0; q < 400; ++q) {
      const Vec3d query{1.2 * u(rng) - 0.1, 1.2 * u(rng) - 0.1, 0.5 * u(rng) - 0.1};
      const int64_t exclude = q % 3 == 0 ? q : -1;
      int64_t best = -1;
      double best_d = radius;
      for (size_t i = 0; i < pts.size(); ++i) {
        if (int64_t(i) == exclude) continue;
        const double d = norm(pts[i] - query);
        if (d < best_d || (best < 0 && d <= best_d)) {
          best = int64_t(i);
          best_d = d;
        }
      }
      const NearestHit hit = tree.nearest(query, radius, exclude);
      ASSERT_EQ(hit.index, best) << "radius " << radius << " query " << q;
      if (best >= 0) EXPECT_NEAR(hit.distance, best_d, 1e-12);
    }
  // A duplicate query: the lower of the two equal indices.
  EXPECT_EQ(tree.nearest(pts[14], 0.0).index, 14);
  EXPECT_EQ(tree.nearest(pts[14], 1.0, 14).index, 3002);
  EXPECT_EQ(KdTree({}).nearest({0, 0, 0}, 1.0).index, -1);
}

TEST(Metrics3d, CentresPerClassCountsTheDistinctCentresOfItsMatchedPoints) {
  // Class 0: two points on centre 0, one on centre 1; class 1: three points on centre 0; class 2: one
  // point beyond the radius (unmatched); a point of no evaluated class (-1) counts for none.
  const std::vector<Vec3d> centres{{0, 0, 0}, {5, 0, 0}};
  const std::vector<Vec3d> gt{{0.01, 0, 0}, {0, 0.02, 0}, {5, 0.05, 0}, {0.1, 0, 0},
                              {0, 0.1, 0},  {0, 0, 0.1},  {2.5, 0, 0}, {4.9, 0, 0}};
  const std::vector<int32_t> labels{0, 0, 0, 1, 1, 1, 2, -1};
  const GtMatching m = match_gt(gt, labels, centres, 0.2);
  EXPECT_EQ(centres_per_class(m, 3), (std::vector<int64_t>{2, 1, 0}));
  EXPECT_EQ(centres_per_class(m, 4), (std::vector<int64_t>{2, 1, 0, 0}));
  EXPECT_THROW(centres_per_class(m, 2), std::invalid_argument);
}

TEST(Metrics3d, BestCentreLabelsAreTheMajorityOfTheMatchedPoints) {
  // One class-0 point right at centre 0, five class-1 points around it, two class-0 points at centre 1:
  // the class of the nearest GT point would label centre 0 wrongly for five points.
  const std::vector<Vec3d> centres{{0, 0, 0}, {5, 0, 0}, {9, 9, 9}};
  std::vector<Vec3d> gt{{0.01, 0, 0}, {5, 0.05, 0}, {4.95, 0, 0}};
  std::vector<int32_t> labels{0, 0, 0};
  for (int i = 0; i < 5; ++i) {
    gt.push_back({0.1, 0.02 * i, 0});
    labels.push_back(1);
  }
  gt.push_back({0.05, 0, 0});  // not evaluated: no vote
  labels.push_back(-1);
  EXPECT_EQ(best_centre_labels(gt, labels, centres, 2, 0.2), (std::vector<int32_t>{1, 0, 0}));
  // A tie goes to the lower class.
  EXPECT_EQ(best_centre_labels({{0, 0, 0}, {0, 0, 0.1}}, {2, 1}, {{0, 0, 0}}, 3, 1.0), (std::vector<int32_t>{1}));
  EXPECT_THROW(best_centre_labels({{0, 0, 0}}, {3}, {{0, 0, 0}}, 3, 1.0), std::invalid_argument);

  // Random: no labelling of the centres gets more matched points right (all 3^6 tried).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3d> pts, cs;
  std::vector<int32_t> cls_of;
  for (int i = 0; i < 200; ++i) {
    pts.push_back({u(rng), u(rng), 0});
    cls_of.push_back(i % 9 == 0 ? -1 : int32_t(rng() % 3));
  }
  for (int i = 0; i < 6; ++i) cs.push_back({u(rng), u(rng), 0.05});
  auto correct = [&](const std::vector<int32_t>& lab) {
    const Scores3d s = score_3d(pts, cls_of, cs, lab, 3, 0.3);
    int64_t tp = 0;
    for (int c = 0; c < 3; ++c) tp += s.confusion.at(c, c);
    return tp;
  };
  const int64_t best = correct(best_centre_labels(pts, cls_of, cs, 3, 0.3));
  int64_t brute = 0;
  for (int code = 0; code < 729; ++code) {
    std::vector<int32_t> lab(6);
    for (int c = 0, x = code; c < 6; ++c, x /= 3) lab[size_t(c)] = x % 3;
    brute = std::max(brute, correct(lab));
  }
  EXPECT_EQ(best, brute);
  EXPECT_GT(best, 0);
}

TEST(Metrics3d, HandComputedMatching) {
  const std::vector<Vec3d> centres{{0, 0, 0}, {1, 0, 0}};
  const std::vector<int32_t> centre_labels{0, 1};
  const std::vector<Vec3d> gt{{0.1, 0, 0}, {0.95, 0, 0}, {5, 0, 0}, {0.5, 0, 0}};
  const std::vector<int32_t> gt_labels{0, 0, 1, -1};  // the last is not evaluated
  const Scores3d s = score_3d(gt, gt_labels, centres, centre_labels, 2, 0.2);
  EXPECT_EQ(s.gt_points, 3);
  EXPECT_EQ(s.matched, 2);
  EXPECT_DOUBLE_EQ(s.coverage, 2.0 / 3);
  EXPECT_NEAR(s.mean_distance, (0.1 + 0.05) / 2, 1e-12);
  EXPECT_EQ(s.confusion.at(0, 0), 1);
  EXPECT_EQ(s.confusion.at(0, 1), 1);
  EXPECT_EQ(s.confusion.total(), 2);                // the unmatched class-1 point is not scored
  EXPECT_DOUBLE_EQ(s.scores.per_class[0].iou, 0.5);  // 1 / (2 + 1 - 1)
  EXPECT_DOUBLE_EQ(s.scores.miou, (0.5 + 0.0) / 2);
  EXPECT_DOUBLE_EQ(s.scores.wiou, 0.5);
  const PointMatching m = match_points(gt, centres, 0.2);
  EXPECT_EQ(m.match, (std::vector<int64_t>{0, 1, -1, -1}));
}
