#include "eval/metrics_2d.h"

#include <stdexcept>
#include <string>

namespace cls {

ConfusionMatrix::ConfusionMatrix(int num_classes)
    : k_(num_classes), counts_(size_t(num_classes) * num_classes, 0), ignored_(size_t(num_classes), 0) {}

namespace {
void check_class(int c, int k, const char* who) {
  if (c < 0 || c >= k)
    throw std::out_of_range(std::string(who) + ": class " + std::to_string(c) + " outside [0, " + std::to_string(k) + ")");
}
}  // namespace

void ConfusionMatrix::add(int gt, int pred, int64_t count) {
  check_class(gt, k_, "ConfusionMatrix::add");
  check_class(pred, k_, "ConfusionMatrix::add");
  counts_[size_t(gt) * k_ + pred] += count;
}

void ConfusionMatrix::add_ignored(int gt, int64_t count) {
  check_class(gt, k_, "ConfusionMatrix::add_ignored");
  ignored_[size_t(gt)] += count;
}

void ConfusionMatrix::add(const ConfusionMatrix& other) {
  if (other.k_ != k_) throw std::invalid_argument("ConfusionMatrix::add: different class counts");
  for (size_t i = 0; i < counts_.size(); ++i) counts_[i] += other.counts_[i];
  for (size_t i = 0; i < ignored_.size(); ++i) ignored_[i] += other.ignored_[i];
}

int64_t ConfusionMatrix::total() const {
  int64_t t = 0;
  for (int64_t c : counts_) t += c;
  return t;
}

int64_t ConfusionMatrix::gt_count(int c) const {
  int64_t t = 0;
  for (int p = 0; p < k_; ++p) t += at(c, p);
  return t;
}

int64_t ConfusionMatrix::pred_count(int c) const {
  int64_t t = 0;
  for (int g = 0; g < k_; ++g) t += at(g, c);
  return t;
}

namespace {
ClassScores class_scores(const ConfusionMatrix& m, int c) {
  ClassScores s;
  s.gt = m.gt_count(c);
  s.pred = m.pred_count(c);
  s.tp = m.at(c, c);
  s.ignored = m.ignored_count(c);
  const int64_t uni = s.gt + s.pred - s.tp;
  s.present = uni > 0 || s.ignored > 0;
  s.iou = uni > 0 ? double(s.tp) / double(uni) : 0;
  s.precision = s.pred > 0 ? double(s.tp) / double(s.pred) : 0;
  s.recall = s.gt > 0 ? double(s.tp) / double(s.gt) : 0;
  return s;
}
}  // namespace

SegmentationScores segmentation_scores(const ConfusionMatrix& m) {
  SegmentationScores s;
  s.samples = m.total();
  int64_t tp = 0, gt_total = 0;
  double iou_sum = 0, weighted = 0;
  for (int c = 0; c < m.num_classes(); ++c) {
    const ClassScores cs = class_scores(m, c);
    s.per_class.push_back(cs);
    tp += cs.tp;
    gt_total += cs.gt;
    weighted += double(cs.gt) * cs.iou;
    if (cs.present) {
      iou_sum += cs.iou;
      ++s.classes_in_miou;
    }
  }
  s.miou = s.classes_in_miou > 0 ? iou_sum / s.classes_in_miou : 0;
  s.wiou = gt_total > 0 ? weighted / double(gt_total) : 0;
  s.accuracy = s.samples > 0 ? double(tp) / double(s.samples) : 0;
  return s;
}

PerImageClassAverages::PerImageClassAverages(int k) : images_(k, 0), iou_(k, 0), precision_(k, 0), recall_(k, 0) {}

void PerImageClassAverages::add_image(const ConfusionMatrix& image) {
  for (int c = 0; c < int(images_.size()); ++c) {
    const ClassScores cs = class_scores(image, c);
    if (cs.gt == 0 && cs.ignored == 0) continue;  // the image does not contain the class
    ++images_[c];
    iou_[c] += cs.iou;
    precision_[c] += cs.precision;
    recall_[c] += cs.recall;
  }
}

ClassScores PerImageClassAverages::mean(int c) const {
  ClassScores s;
  if (images_[c] == 0) return s;
  s.present = true;
  s.iou = iou_[c] / images_[c];
  s.precision = precision_[c] / images_[c];
  s.recall = recall_[c] / images_[c];
  return s;
}

ImageScoring score_labels(const std::vector<int32_t>& gt, const std::vector<int32_t>& pred, int num_classes) {
  if (gt.size() != pred.size()) throw std::invalid_argument("score_labels: GT and prediction differ in size");
  ImageScoring r{ConfusionMatrix(num_classes)};
  r.pixels = int64_t(gt.size());
  for (size_t i = 0; i < gt.size(); ++i) {
    if (gt[i] < 0) continue;
    ++r.valid_gt;
    if (pred[i] < 0) {
      r.confusion.add_ignored(gt[i]);
      continue;
    }
    ++r.scored;
    r.confusion.add(gt[i], pred[i]);
  }
  return r;
}

}  // namespace cls
