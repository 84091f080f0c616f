#pragma once
// Which feature provider a run uses (features/provider_registry.h, "auto" resolved) and the schedule
// that goes with it: the provider's, with the counts the configuration gives instead.
#include <memory>
#include <string>

#include "citymodel/taxonomy.h"
#include "features/provider_registry.h"
#include "pipeline/pipeline_config.h"

namespace cls {

struct FeatureSource {
  std::string models;                         // the provider's name: never "auto"
  std::unique_ptr<FeatureProvider> provider;  // null when the real weights are missing
  std::string missing_weights;                // why, when provider is null
  std::string warning;                        // provider_warning(): in every output of a mechanics run
  std::string note;                           // auto fell back to synthetic: why, and how to get the weights
  Schedule schedule;
};

// cls::UsageError for bad specs.
FeatureSource resolve_feature_source(const PipelineConfig& config, const Taxonomy& taxonomy);

}  // namespace cls
