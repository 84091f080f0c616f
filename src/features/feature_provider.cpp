#include "features/feature_provider.h"

#include "core/error.h"
#include "features/provider_registry.h"

namespace cls {

std::unique_ptr<FeatureProvider> make_feature_provider(const nlohmann::json& spec, const Taxonomy& taxonomy) {
  if (!spec.is_object() || !spec.contains("provider") || !spec.at("provider").is_string())
    throw UsageError("feature provider spec: an object with \"provider\" (a name of `run --models`) is required");
  return feature_provider_info(spec.at("provider").get<std::string>(), "feature provider spec").create(spec, taxonomy);
}

std::string provider_warning(const std::string& provider_name) {
  for (const FeatureProviderInfo& p : feature_providers())
    if (p.name == provider_name) return p.warning;
  return "";
}

}  // namespace cls
