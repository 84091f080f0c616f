#pragma once
// What the stages of one `run` share: the configuration, the output layout, the inputs read and
// validated once (scene, city model, feature provider), the run's record, the fingerprints each stage
// hands on to the stages that use its results, and how the run ends.
#include <map>
#include <string>

#include "citymodel/scene_city_model.h"
#include "core/run_layout.h"
#include "pipeline/feature_source.h"
#include "pipeline/pipeline_config.h"
#include "pipeline/run_record.h"
#include "scene/scene.h"

namespace cls {

enum class PipelineOutcome {
  Finished,        // every stage ran or was reused (or the run stopped where --stop-after said)
  Interrupted,     // SIGINT/SIGTERM: stopped after a checkpoint; the same run resumes
  MissingWeights,  // --models clip without CLIP/SAM weights: stopped before the features
};

struct RunContext {
  PipelineConfig config;  // out_dir resolved
  RunLayout layout;
  Scene scene;           // at train-rgb's size (--max-side): the photometric stages
  Scene language_scene;  // the same views at the language stages' size (--feature-height): label maps,
                         // features, language fields, queries, evaluation
  SceneCityModel city;
  FeatureSource source;
  RunRecord record;
  // The city transform the label maps use: the given one, or the one align refined.
  std::string city_transform;
  // Fingerprints of results, by what they are ("labels", "images", "features", "geometry", ...).
  std::map<std::string, std::string> fingerprints;
  PipelineOutcome outcome = PipelineOutcome::Finished;
  std::string message;  // MissingWeights: what is missing and how to get it

  // The methods trained on identical inputs: CityLangSplat, then the configured baselines.
  std::vector<std::string> methods() const;
  // The photometric model every language field is trained on: the imported PLY, or train-rgb's.
  std::filesystem::path geometry() const;
  const std::string& fingerprint(const std::string& of) const;  // std::logic_error when not set yet
};

// Validates the configuration and reads every input (cls::Error naming the file) before it writes
// anything; then starts the run's record (run.json) with its header.
RunContext open_run(const PipelineConfig& config);

}  // namespace cls
