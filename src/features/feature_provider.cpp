#include "features/feature_provider.h"

#include "core/error.h"
#include "features/clip_provider.h"
#include "features/image_segment_provider.h"
#include "features/synthetic_provider.h"

namespace cls {

std::unique_ptr<FeatureProvider> make_feature_provider(const nlohmann::json& spec, const Taxonomy& taxonomy) {
  if (!spec.is_object() || !spec.contains("provider") || !spec.at("provider").is_string())
    throw UsageError("feature provider spec: an object with \"provider\" (synthetic, clip or clip-tiny) is required");
  const std::string name = spec.at("provider").get<std::string>();
  if (name == "synthetic")
    return std::make_unique<SyntheticFeatureProvider>(SyntheticFeatureProvider::params_from_spec(spec), taxonomy);
  if (name == "image-segments")
    return std::make_unique<ImageSegmentProvider>(ImageSegmentProvider::params_from_spec(spec), taxonomy);
  if (name == "clip" || name == "clip-tiny") return make_clip_provider(spec, taxonomy);
  throw UsageError("unknown feature provider '" + name + "' (known: synthetic, image-segments, clip, clip-tiny)");
}

std::string provider_warning(const std::string& provider_name) {
  if (provider_name == "synthetic")
    return "mechanics: synthetic features, not CLIP (docs/features.md): a benchmark of the pipeline's mechanics, "
           "not a result of the method on real images";
  if (provider_name == "image-segments")
    return "robustness benchmark: segments of the images, features from the exact ground truth under them, not "
           "CLIP/SAM (docs/features.md)";
  if (provider_name == "clip-tiny")
    return "mechanics: tiny random CLIP/SAM models, a smoke test of the code path; every score is meaningless";
  return "";
}

}  // namespace cls
