#pragma once
// Segmentation scores of the paper's evaluation (section 4.1, Tables 1 and 3), from confusion matrices.
//
// Definitions (K evaluated classes; C[g][p] = number of scored samples with GT g and prediction p;
// GT_c = sum_p C[c][p], P_c = sum_g C[g][c], TP_c = C[c][c]):
//   IoU_c       = TP_c / (GT_c + P_c - TP_c)
//   mIoU        = mean of IoU_c over the classes with GT_c + I_c + P_c > 0, I_c = GT samples of class c
//                 whose prediction was ignored (below the threshold, or a label map that does not cover
//                 them): the GT, not a method's coverage, says which classes an image holds, so every
//                 method is scored over the same classes; a class neither labelled nor predicted
//                 carries no information and is left out
//   wIoU        = sum_c GT_c IoU_c / sum_c GT_c (frequency-weighted by GT)
//   accuracy    = sum_c TP_c / sum C (pixel accuracy over the scored samples)
//   precision_c = TP_c / P_c (0 where P_c = 0), recall_c = TP_c / GT_c (0 where GT_c = 0)
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cls {

class ConfusionMatrix {
 public:
  explicit ConfusionMatrix(int num_classes = 0);
  int num_classes() const { return k_; }
  void add(int gt, int pred, int64_t count = 1);  // both in [0, K)
  void add(const ConfusionMatrix& other);
  int64_t at(int gt, int pred) const { return counts_[size_t(gt) * k_ + pred]; }
  int64_t total() const;
  int64_t gt_count(int c) const;    // GT_c
  int64_t pred_count(int c) const;  // P_c
  // GT samples of class c without a prediction (I_c): not errors, but they make the class present.
  void add_ignored(int gt, int64_t count = 1);
  int64_t ignored_count(int c) const { return ignored_[size_t(c)]; }

 private:
  int k_ = 0;
  std::vector<int64_t> counts_;
  std::vector<int64_t> ignored_;
};

struct ClassScores {
  double iou = 0, precision = 0, recall = 0;
  int64_t gt = 0, pred = 0, tp = 0, ignored = 0;
  bool present = false;  // GT_c + I_c + P_c > 0
};

struct SegmentationScores {
  double miou = 0, wiou = 0, accuracy = 0;
  int64_t samples = 0;
  int classes_in_miou = 0;
  std::vector<ClassScores> per_class;  // K entries
};

SegmentationScores segmentation_scores(const ConfusionMatrix& m);

// Table 3's statistic: IoU / precision / recall computed per image, then averaged per class over the
// images whose GT contains the class, scored or ignored (images without it are excluded from its average).
class PerImageClassAverages {
 public:
  explicit PerImageClassAverages(int num_classes);
  void add_image(const ConfusionMatrix& image);
  int images_with(int c) const { return images_[c]; }
  ClassScores mean(int c) const;  // zeros (present = false) for a class no image contains

 private:
  std::vector<int> images_;
  std::vector<double> iou_, precision_, recall_;
};

// Scores one image: gt and pred are class indices in [0, K) or -1 (GT: not labelled / not evaluated;
// prediction: ignored, below the threshold); a sample counts where both are >= 0, a valid GT sample with
// an ignored prediction as I_c. Returns the image's confusion matrix; also counts the valid GT samples and
// the scored ones.
struct ImageScoring {
  ConfusionMatrix confusion;
  int64_t pixels = 0;    // all samples
  int64_t valid_gt = 0;  // gt >= 0
  int64_t scored = 0;    // gt >= 0 and pred >= 0
};
ImageScoring score_labels(const std::vector<int32_t>& gt, const std::vector<int32_t>& pred, int num_classes);

}  // namespace cls
