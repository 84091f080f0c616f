#pragma once
// `citylangsplat query`: open-vocabulary queries on a trained language field (paper 3.3).
// text -> feature provider (the model's, re-created from model.json "provider") -> encoder -> query
// latent q; per Gaussian s_i = cos(q, g_i) at the chosen level, written as `score_<slug>` properties
// of OUT/scores.ply; a threshold or top-k selection per query as OUT/selection_<slug>.ply; per view
// and query the rendered latents decoded to feature space, compared with the text feature: plain
// cosine and LangSplat's relevancy, as turbo-coloured PNG and raw .npy (OUT/maps/<slug>/); and
// OUT/query.json describing all of it; with `objects`, the answer as city objects ranked by the scores of
// their Gaussians (OUT/objects_<slug>.json and .csv, the top rows printed). See docs/query.md.
#include <nlohmann/json.hpp>

#include "features/feature_provider.h"
#include "language/language_model.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace cls {

struct QueryOptions {
  std::string model_dir;
  std::vector<std::string> texts;
  std::string out_dir;          // empty: MODEL/query
  std::string level = "best";   // "1", "2", "3", or "best": per text the level with the highest max score
  bool use_top_k = false;       // selection: top-k instead of threshold
  double threshold = 0.5;       // s_i >= threshold
  int64_t top_k = 0;
  std::vector<std::string> views;  // view names (or names without extension); empty = all
  std::string scene_dir;        // empty: model.json "scene"
  std::string taxonomy_path;    // empty: model.json "taxonomy", else the built-in taxonomy
  bool maps = true;             // relevance maps (needs the scene)
  bool objects = false;         // the city objects ranked by their Gaussians' scores (object_ranking.h):
                                // printed, and OUT/objects_<slug>.json / .csv
  std::string device = "cpu";   // where rendering, decoding and scoring run: cpu or cuda[:N]
};

// Fixed colour ranges of the PNG maps (raw values are in the .npy files).
constexpr double kCosineRange[2] = {0.0, 1.0};
constexpr double kRelevancyRange[2] = {0.0, 1.0};

// Runs the queries and returns what it wrote to OUT/query.json: the model, its scene's views and its
// feature provider read from options.model_dir. cls::UsageError for bad options (empty text, unknown
// level or view names), cls::Error naming the file for a broken model dir.
nlohmann::json run_query(const QueryOptions& options);

// The same on a loaded model (its autoencoder moves to options.device), with the provider its features
// came from and the views of the relevance maps (none: no maps); options.model_dir names the model in the
// record and in errors. What `run` calls with the scene and provider it already holds.
nlohmann::json run_query(LanguageModel& model, FeatureProvider& provider, const std::vector<const SceneView*>& views,
                         const QueryOptions& options);

}  // namespace cls
