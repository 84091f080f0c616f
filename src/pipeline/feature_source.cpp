#include "pipeline/feature_source.h"

#include "core/error.h"

namespace cls {
namespace {

constexpr const char* kWeightsHint =
    "get the weights with `citylangsplat models download openclip-vit-b-16-laion2b sam-vit-h` (see `citylangsplat "
    "models list`), or run the mechanics without them: --models synthetic (synthetic features) or --models tiny "
    "(tiny random models)";

void use_schedule(FeatureSource& s, int rgb, int language, int autoencoder) {
  s.rgb_iterations = rgb;
  s.language_iterations = language;
  s.autoencoder_epochs = autoencoder;
}

}  // namespace

FeatureSource resolve_feature_source(const PipelineConfig& config, const Taxonomy& taxonomy) {
  FeatureSource s;
  nlohmann::json spec;
  ModelsChoice choice = config.models;
  // Weight files named on the command line are a request for the real models: a typo or a broken file
  // must fail, not turn quietly into a synthetic run.
  if (choice == ModelsChoice::Auto && (!config.clip_weights.empty() || !config.sam_weights.empty()))
    choice = ModelsChoice::Real;
  if (choice == ModelsChoice::Real || choice == ModelsChoice::Auto) {
    spec = {{"provider", "clip"}};
    if (!config.clip_weights.empty()) spec["clip"] = config.clip_weights;
    if (!config.sam_weights.empty()) spec["sam"] = config.sam_weights;
    try {
      s.provider = make_feature_provider(spec, taxonomy);
      choice = ModelsChoice::Real;
    } catch (const UsageError&) {
      throw;
    } catch (const Error& e) {
      if (choice == ModelsChoice::Real) {
        s.missing_weights = std::string(e.what()) + "; " + kWeightsHint;
      } else {
        s.note = std::string("no CLIP/SAM weights found (") + e.what() +
                 "): running every stage with synthetic features instead. For the method itself, " + kWeightsHint;
        choice = ModelsChoice::Synthetic;
      }
    }
  }
  if (choice == ModelsChoice::Tiny) spec = {{"provider", "clip-tiny"}, {"seed", 1}};
  if (choice == ModelsChoice::Synthetic) spec = {{"provider", "synthetic"}, {"seed", 1}};
  if (choice == ModelsChoice::ImageSegments)
    spec = {{"provider", "image-segments"}, {"seed", 1}, {"gt", (config.scene_dir / "gt" / "labels").string()}};
  if (!s.provider && s.missing_weights.empty()) s.provider = make_feature_provider(spec, taxonomy);
  s.models = choice;
  if (choice == ModelsChoice::Tiny) use_schedule(s, 100, 20, 5);
  // The bundled example finishes every stage in about 12 minutes on 2 cores with these
  // (docs/benchmarks.md, "Main command").
  if (choice == ModelsChoice::Synthetic || choice == ModelsChoice::ImageSegments) use_schedule(s, 1500, 300, 40);
  if (s.provider) s.warning = provider_warning(s.provider->name());
  if (config.rgb_iterations > 0) s.rgb_iterations = config.rgb_iterations;
  if (config.language_iterations > 0) s.language_iterations = config.language_iterations;
  if (config.autoencoder_epochs > 0) s.autoencoder_epochs = config.autoencoder_epochs;
  return s;
}

}  // namespace cls
