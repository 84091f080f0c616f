#include "features/image_segment_provider.h"

#include <ATen/ATen.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/ximgproc/segmentation.hpp>

#include <cmath>
#include <filesystem>
#include <set>

#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

// Minimum segment sizes per level as a share of the image: SAM's small/medium/large parts.
constexpr std::array<double, 3> kMinShare = {1.0 / 2000, 1.0 / 500, 1.0 / 125};
constexpr std::array<double, 3> kScaleFactor = {1, 4, 16};

// The level-`level` class a level-1 ground-truth class stands for (see the header's limits).
int class_at_level(const Taxonomy& t, int c, int level) {
  if (level == 1 || t.classes[c].level == level) return c;
  if (level == 2) return t.classes[c].level == 1 ? t.find("wall") : -1;
  const int building = t.find("building");
  if (building >= 0) return building;
  for (size_t k = 0; k < t.classes.size(); ++k)
    if (t.classes[k].level == 3) return static_cast<int>(k);
  return -1;
}

}  // namespace

ImageSegmentProvider::ImageSegmentProvider(const ImageSegmentParams& params, const Taxonomy& taxonomy)
    : params_(params), classes_(params.base, taxonomy) {
  if (params_.gt_labels.empty()) throw Error("image-segment provider: no ground-truth label directory (\"gt\")");
  if (!std::filesystem::is_directory(params_.gt_labels))
    fail(params_.gt_labels, "image-segment provider: the ground-truth label directory does not exist (a synth scene's gt/labels)");
  if (!(params_.k > 0) || !(params_.sigma >= 0)) throw Error("image-segment provider: k must be > 0 and sigma >= 0");
  const int n = static_cast<int>(taxonomy.classes.size());
  for (int c = -1; c < n; ++c) directions_.push_back(classes_.class_vector(c));
  for (int level = 1; level <= 3; ++level) {
    auto& map = level_label_[level - 1];
    map.assign(n + 1, 0);
    for (int c = 0; c < n; ++c) map[c + 1] = class_at_level(taxonomy, c, level) + 1;
  }
}

ImageSegmentParams ImageSegmentProvider::params_from_spec(const nlohmann::json& spec) {
  ImageSegmentParams p;
  nlohmann::json base = nlohmann::json::object();
  static const std::set<std::string> own = {"provider", "note", "gt", "k", "sigma"};
  for (const auto& [key, value] : spec.items())
    if (!own.count(key)) base[key] = value;
  p.base = SyntheticFeatureProvider::params_from_spec(base);
  try {
    p.gt_labels = spec.value("gt", p.gt_labels);
    p.k = spec.value("k", p.k);
    p.sigma = spec.value("sigma", p.sigma);
  } catch (const nlohmann::json::exception& e) {
    throw Error(std::string("image-segment provider spec: ") + e.what());
  }
  return p;
}

nlohmann::json ImageSegmentProvider::spec() const {
  const auto& b = params_.base;
  return {{"provider", "image-segments"},
          {"gt", params_.gt_labels},
          {"seed", b.seed},
          {"dim", b.dim},
          {"sam_noise", b.sam_noise},
          {"gml_noise", b.gml_noise},
          {"text_noise", b.text_noise},
          {"k", params_.k},
          {"sigma", params_.sigma},
          {"note", "segments of the RGB image, features from the exact ground truth under them (robustness "
                   "benchmark; not CLIP/SAM)"}};
}

std::array<cv::Mat, 3> ImageSegmentProvider::ground_truth(const FeatureView& view) const {
  const std::string file = (std::filesystem::path(params_.gt_labels) / view.name).replace_extension(".png").string();
  const cv::Mat gt = cv::imread(file, cv::IMREAD_UNCHANGED);
  if (gt.empty()) fail(file, "missing or unreadable ground-truth label image for view " + view.name);
  if (gt.type() != CV_16UC1 || gt.size() != view.rgb.size())
    fail(file, cat("ground-truth labels must be 16-bit, one channel, ", view.rgb.cols, "x", view.rgb.rows,
                   " like the view; got ", gt.cols, "x", gt.rows));
  std::array<cv::Mat, 3> out;
  for (int level = 0; level < 3; ++level) {
    out[level].create(gt.size(), CV_32SC1);
    const auto& map = level_label_[level];
    for (int y = 0; y < gt.rows; ++y)
      for (int x = 0; x < gt.cols; ++x) {
        const int g = gt.at<uint16_t>(y, x);
        if (g >= static_cast<int>(map.size())) fail(file, cat("label ", g, " at (", x, ", ", y, ") is not in the taxonomy"));
        out[level].at<int32_t>(y, x) = map[g];
      }
  }
  return out;
}

std::vector<float> ImageSegmentProvider::mixture(const std::vector<double>& counts, const std::string& who,
                                                 double noise) const {
  std::vector<double> mix(params_.base.dim, 0.0);
  for (size_t c = 0; c < counts.size(); ++c)
    if (counts[c] != 0)
      for (size_t i = 0; i < mix.size(); ++i) mix[i] += counts[c] * directions_[c][i];
  double norm2 = 0;
  for (const double x : mix) norm2 += x * x;
  const double scale = norm2 > 0 ? 1 / std::sqrt(norm2) : 0.0;
  std::vector<float> v(mix.size());
  for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<float>(mix[i] * scale);
  return noisy_unit_vector(std::move(v), params_.base.seed, who, noise);
}

SamSegments ImageSegmentProvider::sam_segments(const FeatureView& view) {
  if (view.rgb.empty() || view.rgb.type() != CV_8UC3) throw Error(view.name + ": the image-segment provider needs an RGB image");
  const std::array<cv::Mat, 3> truth = ground_truth(view);
  const int h = view.rgb.rows, w = view.rgb.cols;
  const size_t hw = size_t(h) * w;
  std::array<std::vector<int32_t>, 3> ids;
  std::array<std::vector<std::vector<float>>, 3> feats;
  for (int level = 0; level < 3; ++level) {
    const auto segmenter = cv::ximgproc::segmentation::createGraphSegmentation(
        params_.sigma, static_cast<float>(params_.k * kScaleFactor[level]),
        std::max(1, static_cast<int>(std::lround(kMinShare[level] * hw))));
    cv::Mat segments;
    segmenter->processImage(view.rgb, segments);  // CV_32S ids 0..n-1
    double top = 0;
    cv::minMaxLoc(segments, nullptr, &top);
    const int n = static_cast<int>(top) + 1;
    std::vector<std::vector<double>> counts(n, std::vector<double>(directions_.size(), 0.0));
    ids[level].resize(hw);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int32_t s = segments.at<int32_t>(y, x);
        ids[level][size_t(y) * w + x] = s;
        counts[s][truth[level].at<int32_t>(y, x)] += 1;
      }
    for (int s = 0; s < n; ++s)
      feats[level].push_back(mixture(counts[s], cat("segment ", view.name, "|", level + 1, "|", s), params_.base.sam_noise));
  }
  return pack_sam_levels(ids, feats, hw, params_.base.dim);
}

at::Tensor ImageSegmentProvider::region_features(const FeatureView& view, const std::vector<RegionMask>& regions) {
  const std::array<cv::Mat, 3> truth = ground_truth(view);
  at::Tensor out = at::zeros({static_cast<int64_t>(regions.size()), params_.base.dim}, at::kFloat);
  for (size_t r = 0; r < regions.size(); ++r) {
    const RegionMask& m = regions[r];
    if (m.level < 1 || m.level > 3 || m.mask.size() != view.rgb.size())
      throw Error(cat(view.name, ": region ", r, " has level ", m.level, " or a mask of another size than the view"));
    std::vector<double> counts(directions_.size(), 0.0);
    for (int y = 0; y < m.mask.rows; ++y)
      for (int x = 0; x < m.mask.cols; ++x)
        if (m.mask.at<uint8_t>(y, x)) counts[truth[m.level - 1].at<int32_t>(y, x)] += 1;
    const std::vector<float> v = mixture(counts, cat("region ", view.name, "|", m.level, "|", r), params_.base.gml_noise);
    std::copy(v.begin(), v.end(), out[r].data_ptr<float>());
  }
  return out;
}

}  // namespace cls
