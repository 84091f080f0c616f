#pragma once
// The text side of a trained language model, shared by `query` and `render`: the taxonomy and the
// feature provider recorded in model.json, and the level that answers a query best.
#include <ATen/core/Tensor.h>
#include <nlohmann/json.hpp>

#include <array>
#include <memory>
#include <string>

#include "citymodel/taxonomy.h"
#include "features/feature_provider.h"
#include "language/language_model.h"

namespace cls {

// `override_path` if given, else what model.json records (a legend array, or a path), else the
// built-in taxonomy. cls::Error naming `model_json` for a recorded path that does not exist.
Taxonomy model_taxonomy(const nlohmann::json& info, const std::string& model_json, const std::string& override_path);

// The scene directory recorded with the model: model.json "scene", else the features stage's
// features.json "scene" (model.json "features" names that directory); "" if neither.
std::string recorded_scene(const nlohmann::json& info);
// The label maps the model's features were made from (features.json "labels_dir"); "" if unknown.
std::string recorded_labels_dir(const nlohmann::json& info);

// A query's level: "1", "2", "3", or "best" (0: LangSplat's choice, score_levels). cls::UsageError
// "<what> must be 1, 2, 3 or best" otherwise.
int parse_query_level(const std::string& level, const std::string& what);

// The model's own feature provider (model.json "provider"), checked against the autoencoder's input
// size. cls::Error naming `model_json` when the spec is missing or the sizes differ.
std::unique_ptr<FeatureProvider> model_provider(const LanguageModel& model, const std::string& model_json,
                                                const Taxonomy& taxonomy);
// cls::Error naming model_json when the provider's features are not the size the model's autoencoder takes.
void check_provider_fits(const LanguageModel& model, const FeatureProvider& provider, const std::string& model_json);

// Per-Gaussian scores of one query latent at each level (gaussian_scores, on the CPU), their maxima, and
// LangSplat's choice: the level with the highest maximum score (ties: the lower level).
struct LevelScores {
  std::array<at::Tensor, 3> scores;  // level 1..3 at index 0..2, N
  std::array<double, 3> max{};       // -1 for an empty model
  int best = 1;
};
LevelScores score_levels(const std::array<at::Tensor, 3>& latents, const at::Tensor& query_latent);
// The same from each level's scores (N, CPU).
LevelScores level_scores(const std::array<at::Tensor, 3>& scores);
// The LevelScores of each text (features P x D) for either field, on the CPU: dense, the cosine of each
// Gaussian's latent with the text's encoded latent (score_levels, paper 3.3); sparse, the cosine of its
// feature with the text's feature (gaussian_cosines).
std::vector<LevelScores> text_level_scores(const LanguageModel& model, const at::Tensor& text_features);

}  // namespace cls
