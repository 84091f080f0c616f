#include "pipeline/feature_source.h"

namespace cls {

FeatureSource resolve_feature_source(const PipelineConfig& config, const Taxonomy& taxonomy) {
  ResolvedProvider r = resolve_provider(config.features, config.scene_dir.string(), taxonomy);
  FeatureSource s;
  s.models = r.name;
  s.provider = std::move(r.provider);
  s.missing_weights = r.missing;
  s.note = r.note;
  if (s.provider) s.warning = provider_warning(s.provider->name());
  s.schedule = feature_provider_info(s.models, "run").schedule;
  for (const auto& [given, into] : {std::pair{config.rgb_iterations, &s.schedule.rgb_iterations},
                                    std::pair{config.language_iterations, &s.schedule.language_iterations},
                                    std::pair{config.autoencoder_epochs, &s.schedule.autoencoder_epochs}})
    if (given > 0) *into = given;
  return s;
}

}  // namespace cls
