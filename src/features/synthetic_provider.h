#pragma once
// The synthetic feature provider: a deterministic stand-in for CLIP/SAM so that the feature,
// autoencoder, language-training, query and evaluation mechanics can be tested and benchmarked
// without weights. It is NOT a model of CLIP: it only has the structure the pipeline relies on
// (one direction per class, noisy per segment, SAM segments sometimes wrong, text of a class prompt
// close to the class direction). docs/features.md lists every parameter.
//
// From a seed:
//   u_c   = a fixed random unit vector per taxonomy class c; u_bg for "background" (no city model);
//   SAM   = per level s/m/l the connected components (8-connected) of the level-1/2/3 class map
//           where M = 1, plus `tile` x `tile` grid cells of the pixels where M = 0; the default
//           level repeats the s level (own rows, same features);
//           feature of a covered segment = normalise(u_class + sam_noise * u_segment), where a
//           fraction `sam_confusion` of covered segments takes another (random) class;
//           feature of a tile = normalise(u_bg + sam_noise * u_segment);
//   regions (CityGML branch) = normalise(u_class + gml_noise * u_region);
//   text  = a prompt or the name of a taxonomy class: normalise(u_class + text_noise * u_phrase);
//           any other text: a random unit vector hashed from the text.
// u_segment / u_region / u_phrase are random unit vectors hashed from the seed and their identity
// (view name, level, index / class / text), so results do not depend on call order.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "features/feature_provider.h"

namespace cls {

struct SyntheticProviderParams {
  uint64_t seed = 1;
  int dim = 512;
  double sam_noise = 0.5;      // |noise| relative to the unit class direction
  double sam_confusion = 0.2;  // fraction of covered SAM segments given a wrong class
  double gml_noise = 0.25;
  double text_noise = 0.05;
  int tile = 32;               // grid cell size (px) of the SAM segments where M = 0
};

class SyntheticFeatureProvider : public FeatureProvider {
 public:
  SyntheticFeatureProvider(const SyntheticProviderParams& params, const Taxonomy& taxonomy);
  // Parameters from a spec (missing keys keep their defaults; unknown keys are a cls::Error).
  static SyntheticProviderParams params_from_spec(const nlohmann::json& spec);

  std::string name() const override { return "synthetic"; }
  nlohmann::json spec() const override;
  int dim() const override { return params_.dim; }
  SamSegments sam_segments(const FeatureView& view) override;
  at::Tensor region_features(const FeatureView& view, const std::vector<RegionMask>& regions) override;
  at::Tensor text_features(const std::vector<std::string>& texts) override;

  // u_c of a class, u_bg (class_id = -1): unit vectors, exposed for tests.
  std::vector<float> class_vector(int class_id) const;
  const SyntheticProviderParams& params() const { return params_; }

 private:
  SyntheticProviderParams params_;
  Taxonomy taxonomy_;
  std::map<std::string, int> prompt_class_;  // every taxonomy prompt and class name -> its class
};

// A unit vector of `dim` standard-normal components drawn from a stream seeded by `key`
// (SplitMix64 + Box-Muller: the same on every platform).
std::vector<float> hashed_unit_vector(uint64_t key, int dim);

// normalise(direction + noise * u), u the hashed unit vector of (seed, who): a segment's or region's
// feature around a class direction, the same for the same identity `who` whatever the call order.
std::vector<float> noisy_unit_vector(std::vector<float> direction, uint64_t seed, const std::string& who, double noise);

// LangSplat's layout [default | s | m | l] from per-level segment ids (-1 = none) over hw pixels and each
// level's segment features; the default level repeats s (own rows, same features).
SamSegments pack_sam_levels(const std::array<std::vector<int32_t>, 3>& ids,
                            const std::array<std::vector<std::vector<float>>, 3>& features, size_t hw, int dim);

}  // namespace cls
