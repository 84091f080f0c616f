#pragma once
// The image-segment provider: the robustness benchmark's stand-in for SAM + CLIP (docs/features.md).
// Unlike the synthetic provider, nothing it produces comes from the label maps, i.e. from the city model
// and the transform the pipeline was given, so a wrong transform or a model without openings shows:
//   SAM   = per level s/m/l Felzenszwalb's graph segmentation of the RGB image alone (OpenCV ximgproc) at
//           scales k, 4k and 16k (minimum segment 1/2000, 1/500, 1/125 of the image);
//   feature of a segment = normalise(m + sam_noise * u_segment), m = normalise(sum_c p_c u_c), p_c the
//           share of the segment's pixels whose exact ground-truth class (the scene's gt/labels, rendered
//           from the true geometry; 0 = background) is c at the segment's level: what a perfect CLIP would
//           see in that crop;
//   regions (CityGML branch) = the same mix over the region's pixels (the region comes from the possibly
//           misaligned label maps, its content from the truth), gml_noise;
//   text  = as the synthetic provider (same seed: same class directions).
// Limits: the ground truth holds level-1 classes only; an opening counts as "wall" at level 2 (a roof
// window too) and every labelled pixel as the building class at level 3. It is not a model of CLIP or
// SAM: segments follow colour edges, not objects, and features are exact up to noise.
#include <string>

#include "features/synthetic_provider.h"

namespace cls {

struct ImageSegmentParams {
  SyntheticProviderParams base;  // seed, dim and noise levels (tile and sam_confusion are unused)
  std::string gt_labels;         // directory of the ground-truth label images, named as the views
  double k = 100;                // Felzenszwalb's scale at level s (m: 4k, l: 16k)
  double sigma = 0.8;            // Gaussian smoothing before segmenting
};

class ImageSegmentProvider : public FeatureProvider {
 public:
  ImageSegmentProvider(const ImageSegmentParams& params, const Taxonomy& taxonomy);
  static ImageSegmentParams params_from_spec(const nlohmann::json& spec);

  std::string name() const override { return "image-segments"; }
  nlohmann::json spec() const override;
  int dim() const override { return params_.base.dim; }
  SamSegments sam_segments(const FeatureView& view) override;
  at::Tensor region_features(const FeatureView& view, const std::vector<RegionMask>& regions) override;
  at::Tensor text_features(const std::vector<std::string>& texts) override { return classes_.text_features(texts); }

 private:
  // The view's ground truth per level: 0 = background, c + 1 = class c (CV_32SC1 each).
  std::array<cv::Mat, 3> ground_truth(const FeatureView& view) const;
  // normalise(normalise(sum_c counts[c] u_c) + noise * u(who)); counts[0] is the background's.
  std::vector<float> mixture(const std::vector<double>& counts, const std::string& who, double noise) const;

  ImageSegmentParams params_;
  SyntheticFeatureProvider classes_;             // class directions and text features
  std::vector<std::vector<float>> directions_;   // [0] background, [c + 1] class c
  std::array<std::vector<int>, 3> level_label_;  // GT label (c + 1) -> label at level 1, 2, 3 (0 = background)
};

}  // namespace cls
