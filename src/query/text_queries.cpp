#include "query/text_queries.h"

#include <filesystem>

#include "core/atomic_file.h"
#include "core/error.h"
#include "query/relevance.h"

namespace cls {
namespace fs = std::filesystem;
using nlohmann::json;

Taxonomy model_taxonomy(const json& info, const std::string& model_json, const std::string& override_path) {
  if (!override_path.empty()) return Taxonomy::load(override_path);
  if (info.contains("taxonomy") && info["taxonomy"].is_array()) return Taxonomy::from_legend(info["taxonomy"].dump(), model_json);
  if (info.contains("taxonomy") && info["taxonomy"].is_string()) {
    const std::string path = info["taxonomy"].get<std::string>();
    if (!path.empty()) {
      if (!fs::exists(path)) fail(model_json, "records taxonomy " + path + ", which does not exist (pass --taxonomy)");
      return Taxonomy::load(path);
    }
  }
  return Taxonomy::builtin();
}

namespace {

// A string of the features stage's features.json (model.json "features" names its directory), "" if
// the model records no features directory, the file is gone or the key is absent.
std::string features_json_string(const json& info, const char* key) {
  if (!info.contains("features") || !info["features"].is_string()) return "";
  const fs::path features_json = fs::path(info["features"].get<std::string>()) / "features.json";
  if (!fs::exists(features_json)) return "";
  try {
    const json fj = json::parse(read_text_file(features_json));
    if (fj.contains(key) && fj[key].is_string()) return fj[key].get<std::string>();
  } catch (const json::exception& e) {
    fail(features_json.string(), std::string("not valid JSON: ") + e.what());
  }
  return "";
}

}  // namespace

std::string recorded_scene(const json& info) {
  if (info.contains("scene") && info["scene"].is_string()) return info["scene"].get<std::string>();
  return features_json_string(info, "scene");
}

std::string recorded_labels_dir(const json& info) { return features_json_string(info, "labels_dir"); }

int parse_query_level(const std::string& level, const std::string& what) {
  if (level == "best") return 0;
  if (level == "1" || level == "2" || level == "3") return level[0] - '0';
  throw UsageError(what + " must be 1, 2, 3 or best, got '" + level + "'");
}

std::unique_ptr<FeatureProvider> model_provider(const LanguageModel& model, const std::string& model_json,
                                                const Taxonomy& taxonomy) {
  if (!model.info.contains("provider") || !model.info["provider"].is_object())
    fail(model_json, "no \"provider\" spec recorded (the feature provider the model was trained with)");
  auto provider = make_feature_provider(model.info["provider"], taxonomy);
  check_provider_fits(model, *provider, model_json);
  return provider;
}

void check_provider_fits(const LanguageModel& model, const FeatureProvider& provider, const std::string& model_json) {
  const int64_t D = model.feature_dim();
  if (provider.dim() != D)
    fail(model_json, "provider '" + provider.name() + "' gives " + std::to_string(provider.dim()) +
                         "-d features, the model's field answers in " + std::to_string(D) + "-d features");
}

LevelScores score_levels(const std::array<at::Tensor, 3>& latents, const at::Tensor& query_latent) {
  std::array<at::Tensor, 3> scores;
  for (int l = 0; l < 3; ++l) scores[l] = gaussian_scores(latents[l], query_latent).cpu();
  return level_scores(scores);
}

std::vector<LevelScores> text_level_scores(const LanguageModel& model, const at::Tensor& text_features) {
  at::NoGradGuard no_grad;
  const at::Tensor features = text_features.to(at::kCPU, at::kFloat);
  std::vector<LevelScores> out;
  if (!model.is_sparse()) {
    const at::Tensor latents = model.autoencoder->encode(features);
    std::array<at::Tensor, 3> on_cpu;
    for (int l = 0; l < 3; ++l) on_cpu[l] = model.latents[l].to(at::kCPU);
    for (int64_t k = 0; k < features.size(0); ++k) out.push_back(score_levels(on_cpu, latents[k]));
    return out;
  }
  std::array<at::Tensor, 3> cosines;  // N x P per level
  for (int l = 0; l < 3; ++l) cosines[l] = gaussian_cosines(model, l + 1, features);
  for (int64_t k = 0; k < features.size(0); ++k)
    out.push_back(level_scores({cosines[0].select(1, k).contiguous(), cosines[1].select(1, k).contiguous(),
                                cosines[2].select(1, k).contiguous()}));
  return out;
}

LevelScores level_scores(const std::array<at::Tensor, 3>& scores) {
  LevelScores s;
  double best_max = -2;
  for (int l = 1; l <= 3; ++l) {
    s.scores[l - 1] = scores[l - 1];
    s.max[l - 1] = s.scores[l - 1].numel() ? s.scores[l - 1].max().item<double>() : -1.0;
    if (s.max[l - 1] > best_max) best_max = s.max[l - 1], s.best = l;  // ties keep the lower level
  }
  return s;
}

}  // namespace cls
