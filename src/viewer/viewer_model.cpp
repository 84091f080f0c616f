#include "viewer/viewer_model.h"

#include <ATen/ATen.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "citymodel/city_transform.h"
#include "citymodel/mesh_ply.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/run_layout.h"
#include "core/strings.h"
#include "language/provenance.h"
#include "query/object_ranking.h"
#include "query/relevance.h"
#include "query/text_queries.h"
#include "raycast/label_export.h"
#include "scene/view_selection.h"
#include "splat/sh.h"

namespace cls {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The held-out views of train-rgb (every 8th by name), drawn apart in the viewer.
constexpr int kTestEvery = 8;

void append_floats(std::string& out, std::initializer_list<float> values) {
  for (float v : values) out.append(reinterpret_cast<const char*>(&v), sizeof v);  // x86/ARM: little-endian
}

std::string gaussians_of(const GaussianModel& g) {
  const int64_t n = g.size();
  const at::Tensor means = g.means.to(at::kFloat).contiguous();
  const at::Tensor scales = g.scales().to(at::kFloat).contiguous();
  const at::Tensor quats = (g.quats / g.quats.norm(2, {1}, true).clamp_min(1e-12)).to(at::kFloat).contiguous();
  const at::Tensor opacity = g.opacities().to(at::kFloat).contiguous();
  // The SH band 0 colour, as 3DGS shows a Gaussian from no particular direction.
  const at::Tensor rgb = (0.5 + kShC0 * g.sh_dc.reshape({n, 3})).clamp(0, 1).to(at::kFloat).contiguous();
  const float *m = means.data_ptr<float>(), *s = scales.data_ptr<float>(), *q = quats.data_ptr<float>(),
              *o = opacity.data_ptr<float>(), *c = rgb.data_ptr<float>();
  std::string out;
  out.reserve(static_cast<size_t>(n) * 14 * sizeof(float));
  for (int64_t i = 0; i < n; ++i)
    append_floats(out, {m[3 * i], m[3 * i + 1], m[3 * i + 2], s[3 * i], s[3 * i + 1], s[3 * i + 2], q[4 * i],
                        q[4 * i + 1], q[4 * i + 2], q[4 * i + 3], o[i], c[3 * i], c[3 * i + 1], c[3 * i + 2]});
  return out;
}

std::string city_mesh_of(const fs::path& ply) {
  const ColouredMesh mesh = read_mesh_ply(ply.string());
  std::string out;
  out.reserve(mesh.triangles.size() * 3 * 6 * sizeof(float));
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& rgb = mesh.colours[t];
    for (int32_t v : mesh.triangles[t]) {
      const Vec3f& p = mesh.vertices[v];
      append_floats(out, {p.x, p.y, p.z, rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f});
    }
  }
  return out;
}

json view_json(const SceneView& v, size_t index, bool test) {
  std::vector<double> R;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R.push_back(v.pose.R.m[r][c]);
  const Vec3d centre = v.pose.center();
  return {{"index", index},      {"name", v.name},
          {"width", v.camera.width}, {"height", v.camera.height},
          {"fx", v.camera.fx},   {"fy", v.camera.fy},
          {"cx", v.camera.cx},   {"cy", v.camera.cy},
          {"R", R},              {"t", {v.pose.t.x, v.pose.t.y, v.pose.t.z}},
          {"center", {centre.x, centre.y, centre.z}},
          {"image", "/api/image/" + std::to_string(index)},
          {"test", test}};
}

// Rows of unit length; a zero row stays zero (gaussian_scores gives such a Gaussian score 0).
at::Tensor normalised_rows(const at::Tensor& x) {
  return (x.to(at::kFloat) / x.to(at::kFloat).norm(2, {-1}, true).clamp_min(1e-30)).contiguous();
}

// `changes`' proposals (RUN/changes/changes.json beside the run's label maps) in the scene frame, for
// GET /api/changes: {"proposals": [{id, class, confidence, width, height, corners}]} (empty without them).
json changes_of(const fs::path& labels) {
  json out{{"proposals", json::array()}};
  if (labels.empty()) return out;
  const fs::path file = RunLayout(labels.parent_path()).changes() / "changes.json";
  const fs::path transform = labels / kLabelsCityTransform;
  if (!fs::exists(file) || !fs::exists(transform)) return out;
  const CityTransform scene_from_crs = read_city_transform(transform.string());
  try {
    const json changes = json::parse(read_text_file(file));  // named: the loop below must not outlive it
    for (const json& p : changes.at("proposals")) {
      json corners = json::array();
      for (const json& c : p.at("corners")) {
        const Vec3d q = scene_from_crs.apply({c.at(0).get<double>(), c.at(1).get<double>(), c.at(2).get<double>()});
        corners.push_back({q.x, q.y, q.z});
      }
      out["proposals"].push_back({{"id", p.at("id")}, {"class", p.at("class")}, {"confidence", p.at("confidence")},
                                  {"width", p.at("width")}, {"height", p.at("height")}, {"corners", corners}});
    }
  } catch (const json::exception& e) {
    fail(file.string(), std::string("not a `changes` output: ") + e.what());
  }
  return out;
}

}  // namespace

std::string run_scene_dir(const fs::path& out) {
  const fs::path run_json = RunLayout(out).run_json();
  if (!fs::exists(run_json)) return "";
  try {
    const json run = json::parse(read_text_file(run_json));
    return run.contains("scene") && run["scene"].is_string() ? run["scene"].get<std::string>() : "";
  } catch (const json::exception& e) {
    fail(run_json.string(), std::string("not valid JSON: ") + e.what());
  }
}

ViewerModel::ViewerModel(const fs::path& model_dir, const std::string& scene_dir)
    : model_(load_language_model(model_dir.string())) {
  at::NoGradGuard no_grad;
  const std::string model_json = LanguageModelFiles{model_dir}.model_json().string();
  const Taxonomy taxonomy = model_taxonomy(model_.info, model_json, "");
  provider_ = model_provider(model_, model_json, taxonomy);

  // Every Gaussian's highest cosine with the canonical phrases per level: with the phrases' latents, normalised
  // (dense), or their features (sparse).
  const at::Tensor canonical_features = provider_->text_features(canonical_phrases()).to(at::kFloat);
  const at::Tensor canonical = model_.is_sparse() ? at::Tensor() : normalised_rows(model_.autoencoder->encode(canonical_features));
  for (int l = 0; l < 3; ++l) {
    if (model_.is_sparse()) {
      canonical_max_[l] = std::get<0>(sparse_cosines(model_.sparse[l], canonical_features).max(1)).contiguous();
      continue;
    }
    normalised_[l] = normalised_rows(model_.latents[l]);
    canonical_max_[l] = std::get<0>(normalised_[l].matmul(canonical.t()).max(1)).contiguous();
  }
  means_ = model_.gaussians.means.to(at::kFloat).contiguous();
  gaussians_ = gaussians_of(model_.gaussians);

  const std::string scene_path = scene_dir.empty() ? recorded_scene(model_.info) : scene_dir;
  json views = json::array();
  if (!scene_path.empty() && fs::exists(scene_path)) {
    SceneOptions options;
    options.check_images = false;
    scene_ = load_scene(scene_path, options);
    const ViewSplit split = split_views(scene_, kTestEvery);
    for (size_t k = 0; k < scene_.views.size(); ++k) {
      const bool test = std::find(split.test.begin(), split.test.end(), &scene_.views[k]) != split.test.end();
      views.push_back(view_json(scene_.views[k], k, test));
    }
  } else {
    log_warn("view: the model's scene " + (scene_path.empty() ? std::string("is not recorded") : scene_path + " is missing") +
             ": no cameras or photos (pass --scene DIR)");
  }
  const fs::path labels = recorded_labels_dir(model_.info);
  if (!labels.empty() && fs::exists(labels / "city_mesh.ply")) city_mesh_ = city_mesh_of(labels / "city_mesh.ply");
  changes_json_ = changes_of(labels);

  objects_json_ = {{"objects", json::array()}};
  if (!model_.objects.objects.empty()) {
    // Each object at the coarsest level it answers for: a wall with its windows, a building whole.
    const at::Tensor object_of = model_.gaussians.extra(kObjectProperty)->values.contiguous();
    const at::Tensor zeros = at::zeros({model_.gaussians.size()}, at::kFloat);
    std::map<int64_t, json> rows;
    for (int l = 1; l <= 3; ++l) {
      ObjectRankingOptions options;
      options.level = l;
      options.min_gaussians = 1;
      const auto ranking = rank_objects(model_.objects, object_of.data_ptr<int32_t>(), zeros.data_ptr<float>(),
                                        means_.data_ptr<float>(), zeros.numel(), options);
      for (json row : object_ranking_json(model_.objects, ranking)) {
        for (const char* score : {"rank", "mean_score", "max_score", "above"}) row.erase(score);
        rows[row["index"].get<int64_t>()] = row;
      }
    }
    for (auto& [index, row] : rows) objects_json_["objects"].push_back(std::move(row));
  }

  json classes = json::array();
  for (size_t k = 0; k < taxonomy.classes.size(); ++k)
    classes.push_back({{"id", k}, {"name", taxonomy.classes[k].name}, {"level", taxonomy.classes[k].level},
                       {"color", taxonomy.classes[k].color}});
  // Bounds of the bulk of the Gaussians (1st to 99th percentile per axis): far floaters and the
  // background would otherwise make the first view a speck.
  at::Tensor lo = at::zeros({3}), hi = at::zeros({3});
  if (means_.size(0) > 0) {
    const at::Tensor sorted = std::get<0>(means_.sort(0));
    const int64_t last = means_.size(0) - 1;
    lo = sorted[static_cast<int64_t>(0.01 * last)];
    hi = sorted[static_cast<int64_t>(0.99 * last)];
  }
  const std::string provider_name = provider_->name();
  model_json_ = {{"gaussians", model_.gaussians.size()},
                 {"model", fs::absolute(model_dir).string()},
                 {"method", model_.info.value("method", "")},
                 {"provider", provider_name},
                 {"warning", provider_warning(provider_name)},
                 {"levels", {1, 2, 3}},
                 {"has_objects", !model_.objects.objects.empty()},
                 {"classes", classes},
                 {"views", views},
                 {"bounds", {{"min", {lo[0].item<double>(), lo[1].item<double>(), lo[2].item<double>()}},
                             {"max", {hi[0].item<double>(), hi[1].item<double>(), hi[2].item<double>()}}}},
                 {"city_mesh", !city_mesh_.empty()},
                 {"changes", changes_json_["proposals"].size()}};
}

std::string ViewerModel::image_path(size_t index) const {
  return index < scene_.views.size() ? scene_.views[index].image_path : "";
}

at::Tensor ViewerModel::text_latent(const std::string& text) {
  const auto it = text_cache_.find(text);
  if (it != text_cache_.end()) return it->second;
  const at::Tensor features = provider_->text_features({text}).to(at::kFloat);
  const at::Tensor q = model_.is_sparse() ? features : normalised_rows(model_.autoencoder->encode(features))[0];
  if (text_cache_.size() > 1000) text_cache_.clear();  // bounded: a long session types many texts
  return text_cache_[text] = q;
}

ViewerAnswer ViewerModel::answer(const ViewerQuery& query) {
  const std::string text = trim_space(query.text);
  if (text.empty()) throw UsageError("the query text is empty");
  if (text.size() > kMaxQueryChars) throw UsageError(cat("the query text has more than ", kMaxQueryChars, " characters"));
  const int fixed = parse_query_level(query.level, "level");
  if (query.mode != "cosine" && query.mode != "relevancy")
    throw UsageError("mode must be cosine or relevancy, got '" + query.mode + "'");
  if (!std::isfinite(query.threshold)) throw UsageError("threshold must be a number");

  std::lock_guard<std::mutex> lock(mutex_);
  at::NoGradGuard no_grad;
  // The page asks for a query's JSON and then its scores: the second request reuses the first's work.
  const std::string key = text + '\n' + query.level + '\n' + query.mode;
  if (key != last_.key) {
    const at::Tensor q = text_latent(text);
    // LangSplat's choice of level: the one with the highest maximum cosine (ties: the lower level).
    std::array<at::Tensor, 3> cosine;
    json level_max = json::object();
    int level = fixed;
    double best = -2;
    for (int l = 1; l <= 3; ++l) {
      if (fixed && l != fixed) continue;
      cosine[l - 1] = model_.is_sparse() ? sparse_cosines(model_.sparse[l - 1], q).select(1, 0).contiguous()
                                         : normalised_[l - 1].mv(q);
      const double m = cosine[l - 1].numel() ? cosine[l - 1].max().item<double>() : -1.0;
      level_max[std::to_string(l)] = m;
      if (!fixed && m > best) best = m, level = l;
    }
    at::Tensor scores = cosine[level - 1];
    // LangSplat's relevancy min_c softmax(10 [cos_q, cos_c])[0] = min_c sigmoid(10 (cos_q - cos_c)), and
    // the sigmoid falls with cos_c: the minimum is at the canonical phrase of highest cosine.
    if (query.mode == "relevancy") scores = at::sigmoid(10.0 * (scores - canonical_max_[level - 1])).contiguous();
    last_ = {key, scores, level, level_max};
  }
  const at::Tensor& scores = last_.scores;
  const int level = last_.level;
  const json& level_max = last_.level_max;

  ViewerAnswer a;
  a.scores = scores;
  a.info = {{"text", text},
            {"level", level},
            {"mode", query.mode},
            {"threshold", query.threshold},
            {"max_score_per_level", level_max},
            {"scores_range", {scores.numel() ? scores.min().item<double>() : 0.0,
                              scores.numel() ? scores.max().item<double>() : 0.0}},
            {"selected", (scores >= query.threshold).sum().item<int64_t>()},
            {"objects", json::array()}};
  if (!model_.objects.objects.empty()) {
    ObjectRankingOptions options;
    options.level = level;
    options.threshold = query.threshold;
    const at::Tensor object_of = model_.gaussians.extra(kObjectProperty)->values.contiguous();
    const std::vector<ObjectScore> ranking =
        rank_objects(model_.objects, object_of.data_ptr<int32_t>(), scores.data_ptr<float>(), means_.data_ptr<float>(),
                     scores.numel(), options);
    a.info["objects"] = object_ranking_json(model_.objects, ranking, query.top);
    a.info["objects_ranked"] = ranking.size();
  }
  return a;
}

}  // namespace cls
