#pragma once
// What `citylangsplat view` answers from, without any HTTP (viewer_server.h serves it): a language
// model loaded once with its text encoder, the per-level normalised latents and the canonical
// phrases' cosines precomputed, so a text query over N Gaussians is three matrix-vector products and
// one pass for the object ranking.
#include <ATen/core/Tensor.h>
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "features/feature_provider.h"
#include "language/language_model.h"
#include "scene/scene.h"

namespace cls {

// The scene a `run` output was made from (OUT/run.json "scene"), "" when OUT is no run directory.
std::string run_scene_dir(const std::filesystem::path& out);

struct ViewerQuery {
  std::string text;
  std::string level = "best";  // "best", "1", "2", "3"
  std::string mode = "cosine"; // "cosine" (s_i = cos(q, g_i), what `query` writes) or "relevancy" (LangSplat's)
  double threshold = 0.5;
  size_t top = 20;             // object rows returned (0 = all)
};

struct ViewerAnswer {
  at::Tensor scores;    // N float32 (CPU), in the order of gaussians_buffer()
  nlohmann::json info;  // text, level, mode, max_score_per_level, selected, objects ...
};

class ViewerModel {
 public:
  // `scene_dir` "" = the scene recorded with the model (views are optional: a moved scene leaves none).
  // "bounds" in model_json() span the 1st to 99th percentile of the centres per axis.
  explicit ViewerModel(const std::filesystem::path& model_dir, const std::string& scene_dir = "");

  const nlohmann::json& model_json() const { return model_json_; }  // GET /api/model
  // N x 14 little-endian float32: x y z, scales, quaternion w x y z, opacity, RGB (SH DC) in [0, 1].
  const std::string& gaussians_buffer() const { return gaussians_; }
  // Non-indexed triangles of the city mesh in the scene frame, x y z r g b per vertex ("" without one).
  const std::string& city_mesh_buffer() const { return city_mesh_; }
  // GET /api/objects: {"objects": [{index, id, class, level, building, part, gaussians, center, radius}]}, every
  // city object that has Gaussians, with those of its parts (a wall with its windows).
  const nlohmann::json& objects_json() const { return objects_json_; }
  // GET /api/changes: `changes`' proposed openings in the scene frame ({"proposals": []} without them).
  const nlohmann::json& changes_json() const { return changes_json_; }
  // The photo of view `index`, or "" when out of range.
  std::string image_path(size_t index) const;

  // cls::UsageError for an empty or over-long text, an unknown level or mode. Thread-safe.
  ViewerAnswer answer(const ViewerQuery& query);

  static constexpr size_t kMaxQueryChars = 200;

 private:
  at::Tensor text_latent(const std::string& text);  // dense: its latent, normalised; sparse: its feature (1 x D); cached

  LanguageModel model_;
  std::unique_ptr<FeatureProvider> provider_;
  std::array<at::Tensor, 3> normalised_;     // dense: per level N x L, rows of unit length (0 for zero latents)
  std::array<at::Tensor, 3> canonical_max_;  // per level N: the highest cosine with a canonical phrase
  at::Tensor means_;                         // N x 3 float32
  Scene scene_;
  nlohmann::json model_json_, objects_json_, changes_json_;
  std::string gaussians_, city_mesh_;
  std::map<std::string, at::Tensor> text_cache_;
  struct LastQuery {
    std::string key;  // text, level and mode
    at::Tensor scores;
    int level = 0;
    nlohmann::json level_max;
  } last_;
  std::mutex mutex_;
};

}  // namespace cls
