#pragma once
// Which feature provider a run uses and the schedule that goes with it: real CLIP/SAM weights (the
// paper's 30k + 30k iterations), tiny random models (a smoke test), synthetic features (the mechanics
// benchmark; sized so the bundled example runs every stage in minutes on 2 cores), or auto: real
// where both weight files are found, synthetic otherwise.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "citymodel/taxonomy.h"
#include "features/feature_provider.h"
#include "pipeline/pipeline_config.h"

namespace cls {

struct FeatureSource {
  ModelsChoice models = ModelsChoice::Real;  // resolved: never Auto
  std::unique_ptr<FeatureProvider> provider;  // null when the real weights are missing
  std::string missing_weights;                // why, when provider is null
  std::string warning;                        // provider_warning(): in every output of a mechanics run
  std::string note;                           // auto fell back to synthetic: why, and how to get the weights
  int rgb_iterations = 30000, language_iterations = 30000, autoencoder_epochs = 100;
};

// Creates the provider for config.models (cls::UsageError for bad specs); the configured iteration
// counts override the source's defaults.
FeatureSource resolve_feature_source(const PipelineConfig& config, const Taxonomy& taxonomy);

}  // namespace cls
