#pragma once
// Where features come from (paper 3.1-3.2). One interface, two implementations:
//  - "clip": SAM automatic masks (LangSplat's AMG, levels default/s/m/l) and CLIP ViT image/text
//    features, from real weights (models/) or, for smoke tests, tiny random models (`--models clip-tiny`);
//  - "synthetic": deterministic stand-ins for tests and the mechanics benchmark: segments from the
//    label maps (connected components per level, grid tiles where M = 0), features = a fixed random
//    unit vector per class plus per-segment noise, text features = the class vector of a taxonomy
//    prompt (a hashed random vector for other text).
#include <ATen/core/Tensor.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "citymodel/taxonomy.h"

namespace cls {

// One view as the providers see it.
struct FeatureView {
  std::string name;              // image name in the scene (e.g. "0003.png")
  cv::Mat rgb;                   // CV_8UC3, RGB order
  std::array<cv::Mat, 3> labels;  // CV_16UC1 C^1..C^3 (0 = none, k = class k-1)
  cv::Mat coverage;              // CV_8UC1 M, 0 / 255
};

struct SamSegments {
  std::vector<int32_t> seg;  // 4 x H x W, LangSplat's offsets (view_features.h)
  at::Tensor features;       // N x D float32, L2-normalised
};

struct RegionMask {
  cv::Mat mask;      // CV_8UC1, nonzero inside
  int level = 1;     // 1..3
  int class_id = -1; // taxonomy class (the synthetic provider uses it; CLIP sees only the pixels)
};

class FeatureProvider {
 public:
  virtual ~FeatureProvider() = default;
  virtual std::string name() const = 0;      // its name in the registry (provider_registry.h)
  virtual nlohmann::json spec() const = 0;   // recorded in features.json; make_feature_provider(spec) re-creates it
  virtual int dim() const = 0;               // feature dimension D (512 for ViT-B)
  // SAM branch: seg maps and one feature per segment.
  virtual SamSegments sam_segments(const FeatureView& view) = 0;
  // V(I ⊙ R) for each region (paper eq. of f^gml): regions.size() x D, L2-normalised.
  virtual at::Tensor region_features(const FeatureView& view, const std::vector<RegionMask>& regions) = 0;
  // T(text): texts.size() x D, L2-normalised.
  virtual at::Tensor text_features(const std::vector<std::string>& texts) = 0;
};

// From a spec: {"provider": "synthetic", "seed": 1, "dim": 512, "sam_noise": ..., ...} or
// {"provider": "clip", "clip": "<weights path>", "sam": "<weights path>", ...} or
// {"provider": "clip-tiny", "seed": 1}; "provider" is a name of the registry (provider_registry.h).
// cls::Error / UsageError with what to do on bad specs or missing weights (the message says how to get
// them: `citylangsplat models download ...`).
std::unique_ptr<FeatureProvider> make_feature_provider(const nlohmann::json& spec, const Taxonomy& taxonomy);

// What every output of a provider other than real CLIP says about itself ("" for "clip" and for names
// the registry does not know): features that are not CLIP's make a benchmark of the mechanics, never a
// result of the method.
std::string provider_warning(const std::string& provider_name);

}  // namespace cls
