#include "query/query_job.h"

#include <ATen/Context.h>
#include <ATen/core/grad_mode.h>
#include <torch/types.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "citymodel/taxonomy.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_file.h"
#include "core/log.h"
#include "core/npy.h"
#include "core/progress.h"
#include "core/run_layout.h"
#include "core/strings.h"
#include "features/feature_provider.h"
#include "language/language_model.h"
#include "language/provenance.h"
#include "query/object_ranking.h"
#include "query/relevance.h"
#include "query/relevance_image.h"
#include "query/selection.h"
#include "query/text_queries.h"
#include "scene/scene.h"
#include "scene/view_selection.h"
#include "splat/ply_gaussians.h"

namespace cls {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

c10::Device parse_device(const std::string& name) {
  try {
    const c10::Device d(name);
    if (d.is_cuda() && !at::hasCUDA())
      throw UsageError("query: --device " + name + ": this build's LibTorch has no CUDA (use cpu)");
    if (!d.is_cpu() && !d.is_cuda()) throw UsageError("query: --device must be cpu or cuda[:N], got '" + name + "'");
    return d;
  } catch (const c10::Error&) {
    throw UsageError("query: --device must be cpu or cuda[:N], got '" + name + "'");
  }
}

json stats_of(const at::Tensor& s) {
  const at::Tensor d = s.to(torch::kFloat64);
  if (d.numel() == 0) return json{{"count", 0}};
  return json{{"count", d.numel()},
              {"min", d.min().item<double>()},
              {"max", d.max().item<double>()},
              {"mean", d.mean().item<double>()},
              {"std", d.numel() > 1 ? d.std().item<double>() : 0.0}};
}

void write_map(const fs::path& dir, const std::string& stem, const at::Tensor& map, const double range[2],
               json& files, const fs::path& out_root) {
  const at::Tensor m = map.to(torch::kCPU, torch::kFloat32).contiguous();
  const std::vector<float> values(m.data_ptr<float>(), m.data_ptr<float>() + m.numel());
  const fs::path npy = dir / (stem + ".npy"), png = dir / (stem + ".png");
  write_npy(npy, make_npy<float>({m.size(0), m.size(1)}, values));
  write_image(png, colour_map(m, MapRange{range[0], range[1]}));
  files.push_back(fs::relative(png, out_root).string());
  files.push_back(fs::relative(npy, out_root).string());
}

// The query's answer as city objects: OUT/objects_<slug>.json and .csv, the top rows printed.
json write_object_ranking(const LanguageModel& model, const std::string& text, const std::string& slug, int level,
                          const at::Tensor& scores, double threshold, const fs::path& out) {
  const at::Tensor object_of = model.gaussians.extra(kObjectProperty)->values.contiguous();
  const at::Tensor s = scores.to(torch::kCPU, torch::kFloat32).contiguous();
  const at::Tensor means = model.gaussians.means.to(torch::kFloat32).contiguous();
  ObjectRankingOptions options;
  options.level = level;
  options.threshold = threshold;
  const std::vector<ObjectScore> ranking = rank_objects(model.objects, object_of.data_ptr<int32_t>(), s.data_ptr<float>(),
                                                        means.data_ptr<float>(), s.numel(), options);
  const json rows = object_ranking_json(model.objects, ranking);
  const std::string json_file = "objects_" + slug + ".json", csv_file = "objects_" + slug + ".csv";
  write_text_atomic(out / json_file, json{{"text", text},
                                          {"level", level},
                                          {"threshold", threshold},
                                          {"min_gaussians", options.min_gaussians},
                                          {"city_model", model.objects.source},
                                          {"objects", rows}}
                                         .dump(2) + "\n");
  write_text_atomic(out / csv_file, object_ranking_csv(model.objects, ranking));
  std::cout << "'" << text << "' (level " << level << "): " << ranking.size() << " city objects ranked by mean score\n";
  for (size_t r = 0; r < rows.size() && r < 10; ++r)
    std::cout << "  " << r + 1 << ". " << rows[r]["class"].get<std::string>() << " " << rows[r]["id"].get<std::string>()
              << " (building " << rows[r]["building"].get<std::string>()
              << (rows[r]["part"] == "" ? "" : ", part " + rows[r]["part"].get<std::string>()) << "): mean "
              << rows[r]["mean_score"].get<double>() << " over " << rows[r]["gaussians"].get<int64_t>() << " Gaussians\n";
  return {{"json", json_file}, {"csv", csv_file}, {"ranked", ranking.size()}, {"top", object_ranking_json(model.objects, ranking, 5)}};
}

}  // namespace

namespace {

// The texts trimmed; cls::UsageError for none or an empty one.
std::vector<std::string> query_texts(const QueryOptions& o) {
  if (o.texts.empty()) throw UsageError("query: give at least one query text");
  std::vector<std::string> texts;
  for (const auto& t : o.texts) {
    if (trim_space(t).empty()) throw UsageError("query: a query text is empty");
    texts.push_back(trim_space(t));
  }
  return texts;
}

}  // namespace

json run_query(const QueryOptions& o) {
  query_texts(o);
  parse_query_level(o.level, "query: --level");
  if (o.use_top_k && o.top_k < 0) throw UsageError("query: --top-k must not be negative");
  if (!fs::is_directory(o.model_dir)) fail(o.model_dir, "not a directory (expected a language model: model.json, point_cloud.ply, latents.safetensors, autoencoder.safetensors)");

  at::NoGradGuard no_grad;
  LanguageModel model = load_language_model(o.model_dir);
  const std::string model_json = LanguageModelFiles{o.model_dir}.model_json().string();
  // The views of the maps, resolved before any work so that a wrong name fails early.
  Scene scene;
  std::vector<const SceneView*> views;
  if (o.maps) {
    const std::string scene_dir = o.scene_dir.empty() ? recorded_scene(model.info) : o.scene_dir;
    if (scene_dir.empty())
      throw UsageError("query: relevance maps need the scene: pass --scene DIR (or --no-maps)");
    SceneOptions scene_options;
    scene_options.check_images = false;
    scene = load_scene(scene_dir, scene_options);
    views = find_views(scene, o.views, "query");
  }
  // The text side: the model's own provider.
  const auto provider = model_provider(model, model_json, model_taxonomy(model.info, model_json, o.taxonomy_path));
  return run_query(model, *provider, views, o);
}

json run_query(LanguageModel& model, FeatureProvider& provider, const std::vector<const SceneView*>& views,
               const QueryOptions& o) {
  const std::vector<std::string> texts = query_texts(o);
  const int fixed_level = parse_query_level(o.level, "query: --level");
  if (o.use_top_k && o.top_k < 0) throw UsageError("query: --top-k must not be negative");
  at::NoGradGuard no_grad;
  if (o.objects && model.objects.objects.empty())
    fail(o.model_dir, "has no city object per Gaussian (city_objects.json): train it again from label maps of this "
                      "version's `raycast` (they write objects.json and object.npy), or query without --objects");
  check_provider_fits(model, provider, LanguageModelFiles{o.model_dir}.model_json().string());
  // Rendering, decoding and scoring run on `device`; the model's CPU tensors stay for writing PLYs.
  const c10::Device device = parse_device(o.device);
  const bool sparse = model.is_sparse();
  if (!sparse) model.autoencoder->to(device);
  GaussianModel geometry_on_device = model.gaussians;
  for (at::Tensor* t : {&geometry_on_device.means, &geometry_on_device.log_scales, &geometry_on_device.quats,
                        &geometry_on_device.opacity_logits})
    *t = t->to(device);
  std::array<at::Tensor, 3> latents_on_device;
  std::array<SparseLevel, 3> sparse_on_device;
  for (int l = 0; l < 3; ++l)
    if (sparse)
      sparse_on_device[l] = {model.sparse[l].indices.to(device), model.sparse[l].weights.to(device), model.sparse[l].codebook.to(device)};
    else
      latents_on_device[l] = model.latents[l].to(device);
  const fs::path out = o.out_dir.empty() ? LanguageModelFiles{o.model_dir}.queries() : fs::path(o.out_dir);
  fs::create_directories(out);

  const at::Tensor text_features = provider.text_features(texts).to(device, torch::kFloat32);  // K x D
  // Dense: the texts' latents, compared with each Gaussian's on `device` (paper 3.3). Sparse: the cosines of
  // each Gaussian's feature with the texts (text_level_scores).
  const at::Tensor query_latents = sparse ? at::Tensor() : model.autoencoder->encode(text_features);  // K x L
  const std::vector<LevelScores> sparse_scores = sparse ? text_level_scores(model, text_features) : std::vector<LevelScores>();
  const std::vector<std::string> slugs = unique_slugs(texts);
  const int64_t K = static_cast<int64_t>(texts.size());

  // Per-Gaussian scores at every level; the chosen level per text.
  GaussianModel scored = model.gaussians;
  json queries = json::array();
  std::vector<int> level_of(K);
  std::vector<at::Tensor> score_of(K);
  for (int64_t k = 0; k < K; ++k) {
    const LevelScores levels = sparse ? sparse_scores[size_t(k)] : score_levels(latents_on_device, query_latents[k]);
    json level_max = json::object();
    for (int l = 1; l <= 3; ++l) level_max[std::to_string(l)] = levels.max[l - 1];
    level_of[k] = fixed_level ? fixed_level : levels.best;
    score_of[k] = levels.scores[level_of[k] - 1];
    scored.extras.push_back({"score_" + slugs[k], score_of[k]});

    const at::Tensor sel = o.use_top_k ? select_top_k(score_of[k], o.top_k) : select_by_threshold(score_of[k], o.threshold);
    GaussianModel subset = subset_gaussians(model.gaussians, sel);
    subset.extras.push_back({"score_" + slugs[k], score_of[k].index_select(0, sel)});
    const std::string sel_file = "selection_" + slugs[k] + ".ply";
    write_gaussians_ply((out / sel_file).string(), subset);

    json selection{{"mode", o.use_top_k ? "top-k" : "threshold"}, {"count", sel.numel()}, {"file", sel_file}};
    if (o.use_top_k) selection["k"] = o.top_k;
    else selection["threshold"] = o.threshold;
    queries.push_back({{"text", texts[k]},
                       {"slug", slugs[k]},
                       {"level", level_of[k]},
                       {"max_score_per_level", level_max},
                       {"scores", stats_of(score_of[k])},
                       {"score_property", "score_" + slugs[k]},
                       {"selection", selection},
                       {"maps", json::array()}});
    if (o.objects)
      queries.back()["objects"] = write_object_ranking(model, texts[k], slugs[k], level_of[k], score_of[k], o.threshold, out);
    log_info("query '" + texts[k] + "': level " + std::to_string(level_of[k]) + ", max score " +
             std::to_string(stats_of(score_of[k]).value("max", 0.0)) + ", " + std::to_string(sel.numel()) +
             " Gaussians selected");
  }
  write_gaussians_ply((out / "scores.ply").string(), scored);

  // Relevance maps per view: one render + decode per (view, level) for all texts of that level.
  json views_done = json::array();
  if (!views.empty()) {
    const at::Tensor canonical = provider.text_features(canonical_phrases()).to(device, torch::kFloat32);
    const std::optional<LinearHeadDecoder> decoder =
        sparse ? std::nullopt : std::optional(linear_head_decoder(*model.autoencoder));
    std::map<int, std::vector<int64_t>> texts_of_level;
    for (int64_t k = 0; k < K; ++k) texts_of_level[level_of[k]].push_back(k);

    const fs::path maps_dir = out / "maps";
    fs::create_directories(maps_dir);
    write_image(maps_dir / "legend_turbo.png", colour_legend());
    for (int64_t k = 0; k < K; ++k) fs::create_directories(maps_dir / slugs[k]);
    Progress progress("relevance maps", views.size() * texts_of_level.size(), "renders");
    for (const SceneView* view : views) {
      const std::string stem = view_stem(view->name);
      for (const auto& [level, ks] : texts_of_level) {
        const at::Tensor idx = torch::tensor(ks, torch::kInt64).to(device);
        const at::Tensor level_texts = text_features.index_select(0, idx);
        const RelevanceMaps m =
            sparse ? relevance_maps(geometry_on_device, sparse_on_device[level - 1], view->camera, view->pose, level_texts,
                                    canonical)
                   : relevance_maps(geometry_on_device, latents_on_device[level - 1], *decoder, view->camera, view->pose,
                                    level_texts, canonical);
        for (size_t j = 0; j < ks.size(); ++j) {
          const int64_t k = ks[j];
          json& files = queries[k]["maps"];
          write_map(maps_dir / slugs[k], stem + "_cosine", m.cosine[j], kCosineRange, files, out);
          write_map(maps_dir / slugs[k], stem + "_relevancy", m.relevancy[j], kRelevancyRange, files, out);
        }
        progress.advance();
      }
      views_done.push_back({{"name", view->name}, {"width", view->camera.width}, {"height", view->camera.height}});
    }
    progress.finish();
  }

  json result{{"model", fs::absolute(o.model_dir).string()},
              {"method", model.info.value("method", "")},
              {"provider", provider.spec()},
              {"level_requested", o.level},
              {"device", device.str()},
              {"gaussians", model.gaussians.size()},
              {"queries", queries},
              {"scores_file", "scores.ply"},
              {"canonical_phrases", canonical_phrases()},
              {"views", views_done}};
  if (!views.empty())
    result["maps"] = {{"colormap", "turbo (OpenCV COLORMAP_TURBO): dark blue = range low, dark red = range high"},
                      {"legend", "maps/legend_turbo.png"},
                      {"cosine_range", {kCosineRange[0], kCosineRange[1]}},
                      {"relevancy_range", {kRelevancyRange[0], kRelevancyRange[1]}},
                      {"raw", "float32 H x W .npy beside each PNG"}};
  write_text_atomic(out / "query.json", result.dump(2) + "\n");
  return result;
}

}  // namespace cls
