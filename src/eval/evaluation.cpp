// The paper's evaluation (section 4.1 / 4.3). Definitions of every number: docs/evaluation.md.
#include "eval/evaluation.h"

#include <ATen/core/grad_mode.h>
#include <torch/types.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <opencv2/imgcodecs.hpp>
#include <set>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_file.h"
#include "core/log.h"
#include "core/progress.h"
#include "citymodel/city_transform.h"
#include "eval/class_map.h"
#include "eval/gt_images.h"
#include "eval/gt_projection.h"
#include "eval/labelled_points.h"
#include "eval/metrics_2d.h"
#include "eval/metrics_3d.h"
#include "raycast/label_export.h"
#include "raycast/label_map_io.h"
#include "scene/view_selection.h"
#include "eval/evaluation_tables.h"
#include "query/relevance.h"

namespace fs = std::filesystem;

namespace cls {
namespace {

// The evaluated classes (taxonomy ids, ascending): the named ones, or every class in the GT.
// `labels`: every GT label (cloud points, image pixels), taxonomy ids, negative = none.
std::vector<int> evaluated_classes(const Taxonomy& taxonomy, const std::vector<int32_t>& labels,
                                   const EvaluationOptions& o) {
  std::vector<int> ids;
  if (!o.classes.empty()) {
    for (const std::string& name : o.classes) {
      const int id = taxonomy.find(name);
      if (id < 0) throw UsageError("evaluate: class '" + name + "' is not in the taxonomy");
      ids.push_back(id);
    }
  } else {
    std::set<int> present;
    int64_t outside = 0;
    for (int32_t l : labels) {
      if (l < 0) continue;
      if (l >= int(taxonomy.classes.size())) {
        ++outside;
        continue;
      }
      present.insert(l);
    }
    if (outside > 0)
      log_warn(cat("evaluate: ", outside, " GT labels have a class id outside the taxonomy; they are not evaluated"));
    ids.assign(present.begin(), present.end());
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids.empty())
    fail(o.gt_points.empty() ? o.gt_images : o.gt_points, "no evaluated class (the GT has no label of the taxonomy)");
  return ids;
}

// Our "fallback" level of a class (the paper names no rule for which level answers a class): the subpart
// map carries parts (docs/conventions.md).
int fallback_level(const SemanticClass& c) { return c.level == 3 ? 3 : 1; }

// The level whose field answers a class: its fallback level, or with LangSplat's rule the level whose
// map has the highest maximum (`max_at(level)`; ties: the lower level).
int answering_level(int fallback, bool langsplat_rule, const std::vector<int>& levels,
                    const std::function<double(int)>& max_at) {
  if (!langsplat_rule) return fallback;
  int level = fallback;
  double best = -1e300;
  for (int l : levels)
    if (const double m = max_at(l); m > best) {
      best = m;
      level = l;
    }
  return level;
}

std::vector<int> available_levels(const LanguageModel& model) {
  std::vector<int> levels;
  for (int l = 1; l <= 3; ++l)
    if (model.has_level(l)) levels.push_back(l);
  if (levels.empty()) throw Error("evaluate: the language model has no latents");
  return levels;
}

nlohmann::json scores_json(const ClassScores& s) {
  return {{"iou", s.iou}, {"precision", s.precision}, {"recall", s.recall}, {"gt", s.gt}, {"pred", s.pred}, {"tp", s.tp},
          {"ignored_gt", s.ignored}};
}

nlohmann::json confusion_json(const ConfusionMatrix& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int g = 0; g < m.num_classes(); ++g) {
    nlohmann::json row = nlohmann::json::array();
    for (int p = 0; p < m.num_classes(); ++p) row.push_back(m.at(g, p));
    rows.push_back(row);
  }
  return rows;
}

// Per-class relevance normalised to [0, 1] by its own min and max (no softmax, paper 4.3); a constant
// map carries no information and becomes 0.
at::Tensor minmax_normalise(const at::Tensor& map) {
  const at::Tensor lo = map.min(), hi = map.max();
  const double range = (hi - lo).item<double>();
  if (!(range > 1e-12)) return torch::zeros_like(map);
  return (map - lo) / range;
}

}  // namespace

std::vector<std::string> evaluation_phrases(const SemanticClass& c, const std::string& phrases) {
  if (phrases != "held-out" && phrases != "all")
    throw UsageError("evaluate: phrases must be 'held-out' or 'all', got '" + phrases + "'");
  if (c.prompts.empty()) throw Error("class_prototypes: class '" + c.name + "' has no prompts");
  if (phrases == "all" || c.prompts.size() == 1) return c.prompts;
  return {c.prompts.begin() + 1, c.prompts.end()};
}

at::Tensor class_prototypes(FeatureProvider& provider, const Taxonomy& taxonomy, const std::vector<int>& classes,
                            const std::string& phrases) {
  at::NoGradGuard no_grad;
  std::vector<at::Tensor> rows;
  for (int id : classes) {
    if (id < 0 || id >= int(taxonomy.classes.size())) throw Error("class_prototypes: class id " + std::to_string(id) + " outside the taxonomy");
    const at::Tensor t =
        provider.text_features(evaluation_phrases(taxonomy.classes[size_t(id)], phrases)).to(torch::kCPU, torch::kFloat32);
    rows.push_back(unit_rows(unit_rows(t).mean(0)));
  }
  return torch::stack(rows, 0);
}

namespace {

// What every evaluation shares: the GT cloud (empty with label images alone), the class map, the evaluated
// classes and their names and colours.
struct EvaluatedClasses {
  LabelledPoints gt;
  std::optional<ClassMap> map;
  std::vector<int> ids;      // taxonomy ids, ascending
  std::vector<int> eval_of;  // taxonomy id -> evaluated index or -1
  nlohmann::json names = nlohmann::json::array();
  std::vector<std::array<unsigned char, 3>> colours;
  int size() const { return int(ids.size()); }
  int32_t to_eval(int32_t taxonomy_id) const {
    return taxonomy_id >= 0 && taxonomy_id < int32_t(eval_of.size()) ? eval_of[size_t(taxonomy_id)] : -1;
  }
};

EvaluatedClasses load_evaluated_classes(const Scene& scene, const Taxonomy& taxonomy, const EvaluationOptions& options) {
  EvaluatedClasses e;
  if (options.gt_points.empty() && options.gt_images.empty())
    throw UsageError("evaluate: no ground truth: give a labelled cloud, label images, or both");
  if (!options.class_map.empty()) e.map = read_class_map(options.class_map, taxonomy);
  const ClassMap* map = e.map ? &*e.map : nullptr;
  if (!options.gt_points.empty()) e.gt = read_labelled_points(options.gt_points, options.gt_class_property, map);
  if (!options.gt_transform.empty()) {
    // In double: a CRS's large coordinates cancel against the transform's translation before any rounding.
    const CityTransform t = read_city_frame(options.gt_transform).transform;
    for (Vec3d& p : e.gt.positions) p = t.apply(p);
  }
  std::vector<int32_t> labels = e.gt.labels;
  if (!options.gt_images.empty()) {
    size_t masks = 0;
    for (const SceneView& v : scene.views)
      if (const auto ids = read_gt_image(options.gt_images, v, map)) {
        ++masks;
        std::set<int32_t> present(ids->begin(), ids->end());
        labels.insert(labels.end(), present.begin(), present.end());
      }
    if (masks == 0) fail(options.gt_images, "no label image of any view (<photo name>.png)");
    log_info(cat("evaluate: label images of ", masks, " of ", scene.views.size(), " views"));
  }
  e.ids = evaluated_classes(taxonomy, labels, options);
  e.eval_of.assign(taxonomy.classes.size(), -1);
  for (int k = 0; k < e.size(); ++k) {
    e.eval_of[size_t(e.ids[k])] = k;
    e.colours.push_back(taxonomy.classes[size_t(e.ids[k])].color);
    e.names.push_back(taxonomy.classes[size_t(e.ids[k])].name);
  }
  return e;
}

// Confusion counts and per-image class averages over a set of images (Tables 1 and 3).
struct Scores2d {
  ConfusionMatrix total;
  PerImageClassAverages per_image;
  int64_t pixels = 0, valid_gt = 0, scored = 0;
  explicit Scores2d(int K) : total(K), per_image(K) {}

  ImageScoring add(const std::vector<int32_t>& gt, const std::vector<int32_t>& pred) {
    ImageScoring s = score_labels(gt, pred, total.num_classes());
    total.add(s.confusion);
    per_image.add_image(s.confusion);
    pixels += s.pixels;
    valid_gt += s.valid_gt;
    scored += s.scored;
    return s;
  }

  nlohmann::json json(const nlohmann::json& names) const {
    const SegmentationScores s = segmentation_scores(total);
    nlohmann::json per_class = nlohmann::json::object(), pooled = nlohmann::json::object();
    for (int k = 0; k < total.num_classes(); ++k) {
      const ClassScores m = per_image.mean(k);
      per_class[names[k].get<std::string>()] = {
          {"iou", m.iou}, {"precision", m.precision}, {"recall", m.recall}, {"images", per_image.images_with(k)}};
      pooled[names[k].get<std::string>()] = scores_json(s.per_class[size_t(k)]);
    }
    return {{"gt_coverage", pixels ? double(valid_gt) / double(pixels) : 0.0},
            {"coverage", valid_gt ? double(scored) / double(valid_gt) : 0.0},
            {"miou", s.miou},
            {"wiou", s.wiou},
            {"accuracy", s.accuracy},
            {"classes_in_miou", s.classes_in_miou},
            {"pixels", pixels},
            {"valid_gt_pixels", valid_gt},
            {"scored_pixels", scored},
            {"per_class", per_class},
            {"per_class_pooled", pooled},
            {"confusion", confusion_json(total)}};
  }
};

// A method's 2D prediction for one view: evaluated class index per pixel (row-major H x W), -1 = none.
// It may add fields to the view's record (e.g. the levels it read).
// A view's predictions, one class per pixel (-1 none): the scored reading first, then the alternative
// readings evaluate_2d was named (scored on the same views, reported apart).
using Predict2d =
    std::function<std::vector<std::vector<int32_t>>(const SceneView& view, size_t index, nlohmann::json& record)>;

// The 2D evaluation (paper 4.3) of any prediction: GT label images projected from the cloud, scored on
// valid GT pixels ("2d") and, when options.labels_dir is set, on those the city model covers (M = 1,
// "2d_covered"). `visible` (optional, gt.size()) receives which GT points win some pixel of some view.
// `alternatives`: the names of the readings after the first (out["2d_<name>"], the held-out views).
nlohmann::json evaluate_2d(const Scene& scene, const EvaluatedClasses& ec, const EvaluationOptions& options,
                           const Predict2d& predict, std::vector<uint8_t>* visible,
                           const std::vector<std::string>& alternatives = {}) {
  const int K = ec.size();
  GtProjectionOptions popt;
  popt.point_radius = options.gt_point_radius;
  const bool cloud = ec.gt.size() > 0;
  const double radius = cloud ? footprint_radius(ec.gt, popt) : 0.0;
  const std::vector<fs::path> label_dirs =
      options.labels_dir.empty() ? std::vector<fs::path>() : label_map_dirs(scene, options.labels_dir);
  // With a split, "2d" scores the held-out views (no photometric or language training saw them) and
  // "2d_train" the others.
  std::set<const SceneView*> held_out;
  for (const SceneView* v : split_views(scene, options.test_every).test) held_out.insert(v);
  Scores2d all(K), covered(K), train(K);
  std::vector<Scores2d> alternative(alternatives.size(), Scores2d(K));
  nlohmann::json views = nlohmann::json::array();
  const fs::path view_dir = options.out_dir.empty() ? fs::path() : fs::path(options.out_dir) / "views";
  if (!view_dir.empty() && options.write_view_images) fs::create_directories(view_dir);
  Progress progress("evaluate 2D", scene.views.size(), "views");
  for (size_t i = 0; i < scene.views.size(); ++i) {
    const SceneView& v = scene.views[i];
    const int H = v.camera.height, W = v.camera.width;
    std::vector<int32_t> gt_labels(size_t(H) * W, -1);
    if (cloud) {  // the projected cloud: the 2D GT without label images; which points some pixel sees
      cv::Mat winner;
      const cv::Mat proj = project_gt_labels(ec.gt, v.camera, v.pose, radius, popt, nullptr, &winner);
      if (visible)
        for (int y = 0; y < H; ++y)
          for (int x = 0; x < W; ++x)
            if (const int32_t w = winner.at<int32_t>(y, x); w >= 0) (*visible)[size_t(w)] = 1;
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) gt_labels[size_t(y) * W + x] = ec.to_eval(proj.at<int32_t>(y, x));
    }
    if (!options.gt_images.empty()) {  // a view without its label image has no 2D GT
      const auto ids = read_gt_image(options.gt_images, v, ec.map ? &*ec.map : nullptr);
      for (size_t p = 0; p < gt_labels.size(); ++p) gt_labels[p] = ids ? ec.to_eval((*ids)[p]) : -1;
    }

    nlohmann::json record = {{"name", v.name}};
    const bool scored = options.test_every == 0 || held_out.count(&v);
    if (options.test_every > 0) record["held_out"] = scored;
    const std::vector<std::vector<int32_t>> readings = predict(v, i, record);
    const std::vector<int32_t>& pred = readings.front();
    if (scored)
      for (size_t a = 0; a < alternatives.size(); ++a) alternative[a].add(gt_labels, readings.at(a + 1));
    const ImageScoring s = (scored ? all : train).add(gt_labels, pred);
    const SegmentationScores vs = segmentation_scores(s.confusion);
    record["gt_coverage"] = s.pixels ? double(s.valid_gt) / double(s.pixels) : 0.0;
    record["coverage"] = s.valid_gt ? double(s.scored) / double(s.valid_gt) : 0.0;
    record["miou"] = vs.miou;
    record["wiou"] = vs.wiou;
    record["accuracy"] = vs.accuracy;
    if (!label_dirs.empty()) {
      const cv::Mat m = read_label_png(label_dirs[i] / "coverage.png", CV_8UC1, H, W);
      std::vector<int32_t> gt_covered = gt_labels;
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
          if (m.at<uint8_t>(y, x) == 0) gt_covered[size_t(y) * W + x] = -1;
      Scores2d one(K);
      record["miou_covered"] = segmentation_scores((scored ? covered : one).add(gt_covered, pred).confusion).miou;
    }
    views.push_back(record);
    if (!view_dir.empty() && options.write_view_images) {
      const std::string stem = fs::path(v.name).stem().string();
      write_image(view_dir / (stem + "_gt.png"), colourise(gt_labels, H, W, ec.colours, cv::Vec3b(0, 0, 0)));
      write_image(view_dir / (stem + "_pred.png"), colourise(pred, H, W, ec.colours, cv::Vec3b(64, 64, 64)));
    }
    progress.advance();
  }
  nlohmann::json out = {{"2d", all.json(ec.names)}};
  if (cloud) out["gt_point_radius"] = radius;
  out["2d"]["views"] = views;
  out["2d"]["test_every"] = options.test_every;
  out["2d"]["views_scored"] = options.test_every > 0 ? held_out.size() : scene.views.size();
  if (options.test_every > 0 && held_out.size() < scene.views.size()) out["2d_train"] = train.json(ec.names);
  if (!label_dirs.empty()) out["2d_covered"] = covered.json(ec.names);
  for (size_t a = 0; a < alternatives.size(); ++a) out["2d_" + alternatives[a]] = alternative[a].json(ec.names);
  return out;
}

nlohmann::json common_json(const EvaluatedClasses& ec, const EvaluationOptions& options) {
  nlohmann::json j = {{"classes", ec.names},
          {"threshold_2d", options.threshold_2d},
          {"match_radius", options.match_radius},
          {"gt_points", options.gt_points},
          {"labels", options.labels_dir}};
  if (!options.class_map.empty()) j["class_map"] = options.class_map;
  if (!options.gt_transform.empty()) j["gt_transform"] = options.gt_transform;
  if (!options.gt_images.empty()) j["gt_images"] = options.gt_images;
  return j;
}

}  // namespace

nlohmann::json evaluate_model(const Scene& scene, const LanguageModel& model, FeatureProvider& provider,
                              const Taxonomy& taxonomy, const EvaluationOptions& options) {
  if (options.level_rule != "fallback" && options.level_rule != "langsplat")
    throw UsageError("evaluate: level rule must be 'fallback' or 'langsplat', got '" + options.level_rule + "'");
  at::NoGradGuard no_grad;
  const EvaluatedClasses ec = load_evaluated_classes(scene, taxonomy, options);
  const int K = ec.size();
  if (options.test_every > 0 && model.info.contains("test_every") && model.info["test_every"] != options.test_every)
    log_warn(cat("evaluate: the model was trained holding out every ", model.info["test_every"].dump(),
                 "-th view (0 = none), the 2D scores use every ", options.test_every,
                 "-th as held out: some of them were trained on"));
  const at::Tensor prototypes = class_prototypes(provider, taxonomy, ec.ids, options.phrases);
  const std::vector<int> levels = available_levels(model);
  const bool langsplat_rule = options.level_rule == "langsplat";
  std::vector<int> class_level(K);
  for (int k = 0; k < K; ++k) {
    class_level[k] = fallback_level(taxonomy.classes[size_t(ec.ids[k])]);
    if (!langsplat_rule && !model.has_level(class_level[k]))
      throw Error("evaluate: class '" + taxonomy.classes[size_t(ec.ids[k])].name + "' is read at level " +
                  std::to_string(class_level[k]) + ", which the language model does not have");
  }
  std::set<int> used_levels;
  if (langsplat_rule) used_levels.insert(levels.begin(), levels.end());
  else used_levels.insert(class_level.begin(), class_level.end());

  // ---- 2D: per class relevance normalised to [0, 1], argmax per pixel, below the threshold ignored. The
  // relevance is the plain cosine ("relevance maps computed without softmax", paper 4.3: the scored
  // reading); LangSplat's relevancy against its canonical phrases is the other reading ("2d_relevancy"),
  // on the same views, levels and threshold.
  const at::Tensor canonical = provider.text_features(canonical_phrases()).to(torch::kCPU, torch::kFloat32);
  std::vector<uint8_t> visible(ec.gt.size(), 0);  // GT points nearest at some pixel of some view
  const Predict2d predict = [&](const SceneView& v, size_t, nlohmann::json& record) {
    std::map<int, RelevanceMaps> rel;  // level -> K x H x W raw cosine and relevancy
    for (int l : used_levels) rel[l] = relevance_maps(model, l, v, prototypes, canonical);
    std::vector<at::Tensor> cosine, relevancy;
    nlohmann::json chosen = nlohmann::json::array();
    for (int k = 0; k < K; ++k) {
      const int level = answering_level(class_level[k], langsplat_rule, levels,
                                        [&](int l) { return rel[l].cosine[k].max().item<double>(); });
      chosen.push_back(level);
      cosine.push_back(minmax_normalise(rel[level].cosine[k].to(torch::kCPU)));
      relevancy.push_back(minmax_normalise(rel[level].relevancy[k].to(torch::kCPU)));
    }
    record["levels"] = chosen;
    const auto classify = [&](const std::vector<at::Tensor>& maps) {
      const auto [best, arg] = torch::stack(maps, 0).max(0);
      const at::Tensor pred_t =
          torch::where(best >= options.threshold_2d, arg, torch::full_like(arg, -1)).to(torch::kInt32).contiguous();
      const int32_t* pp = pred_t.data_ptr<int32_t>();
      return std::vector<int32_t>(pp, pp + pred_t.numel());
    };
    return std::vector<std::vector<int32_t>>{classify(cosine), classify(relevancy)};
  };
  nlohmann::json result = evaluate_2d(scene, ec, options, predict, &visible, {"relevancy"});
  result["relevance"] = "cosine";

  if (ec.gt.size() > 0) {  // 3D needs a labelled cloud (label images alone score 2D only)
    // ---- 3D: every Gaussian's decoded latent argmax over the prototypes; GT points matched to centres.
    const int64_t N = model.gaussians.size();
    std::map<int, at::Tensor> gcos;
    for (int l : used_levels) gcos[l] = gaussian_cosines(model, l, prototypes);
    std::vector<at::Tensor> cols;
    nlohmann::json levels_3d = nlohmann::json::array();
    for (int k = 0; k < K; ++k) {
      const int level = answering_level(class_level[k], langsplat_rule, levels, [&](int l) {
        return N > 0 ? gcos[l].select(1, k).max().item<double>() : 0.0;
      });
      levels_3d.push_back(level);
      cols.push_back(gcos[level].select(1, k));
    }
    std::vector<int32_t> centre_labels(size_t(N), 0);
    if (N > 0) {
      const at::Tensor arg = torch::stack(cols, 1).argmax(1).to(torch::kInt32).contiguous();
      std::copy(arg.data_ptr<int32_t>(), arg.data_ptr<int32_t>() + N, centre_labels.begin());
    }
    const at::Tensor means = model.gaussians.means.to(torch::kCPU, torch::kFloat64).contiguous();
    std::vector<Vec3d> centres(static_cast<size_t>(N));
    for (int64_t i = 0; i < N; ++i) {
      const double* m = means.data_ptr<double>() + 3 * i;
      centres[size_t(i)] = {m[0], m[1], m[2]};
    }
    std::vector<int32_t> gt_eval(ec.gt.size());
    for (size_t i = 0; i < ec.gt.size(); ++i) gt_eval[i] = ec.to_eval(ec.gt.labels[i]);
    auto scores_3d_json = [&](const std::vector<int32_t>& labels) {
      const GtMatching matching = match_gt(ec.gt.positions, labels, centres, options.match_radius);
      const Scores3d s3 = score_matched(matching, centre_labels, K);
      // What these Gaussians allow: the labelling that gets the most matched GT points right.
      const Scores3d best = score_matched(matching, best_centre_labels(matching, K), K);
      const std::vector<int64_t> support = centres_per_class(matching, K);
      auto per_class_of = [&](const Scores3d& s) {
        nlohmann::json per_class = nlohmann::json::object();
        for (int k = 0; k < K; ++k) {
          nlohmann::json c = scores_json(s.scores.per_class[size_t(k)]);
          c["gaussians"] = support[size_t(k)];
          per_class[ec.names[k].get<std::string>()] = c;
        }
        return per_class;
      };
      return nlohmann::json{{"coverage", s3.coverage},
                            {"mean_distance", s3.mean_distance},
                            {"miou", s3.scores.miou},
                            {"wiou", s3.scores.wiou},
                            {"accuracy", s3.scores.accuracy},
                            {"classes_in_miou", s3.scores.classes_in_miou},
                            {"gt_points", s3.gt_points},
                            {"matched", s3.matched},
                            {"gaussians", N},
                            {"levels", levels_3d},
                            {"per_class", per_class_of(s3)},
                            {"confusion", confusion_json(s3.confusion)},
                            {"best_labelling",
                             {{"miou", best.scores.miou},
                              {"wiou", best.scores.wiou},
                              {"accuracy", best.scores.accuracy},
                              {"per_class", per_class_of(best)}}}};
    };
    // The paper's 3D scores use every GT point; a synthetic cloud also samples surfaces no view sees
    // (e.g. a building's ground surface), whose Gaussians no loss reaches: "3d_visible" keeps the GT
    // points that are the nearest point at some pixel of some view.
    result["3d"] = scores_3d_json(gt_eval);
    for (size_t i = 0; i < ec.gt.size(); ++i)
      if (!visible[i]) gt_eval[i] = -1;
    result["3d_visible"] = scores_3d_json(gt_eval);
  }

  nlohmann::json levels_json = nlohmann::json::array();
  for (int l : class_level) levels_json.push_back(l);
  result.update(common_json(ec, options));
  result["method"] = model.info.value("method", std::string("unknown"));
  result["class_levels"] = levels_json;
  result["level_rule"] = options.level_rule;
  result["phrases"] = options.phrases;
  result["provider"] = provider.spec();
  return result;
}

nlohmann::json evaluate_label_maps(const Scene& scene, const Taxonomy& taxonomy, const EvaluationOptions& options) {
  if (options.labels_dir.empty()) throw UsageError("evaluate: the label-map reference needs the label maps' directory");
  check_label_legend(options.labels_dir, taxonomy);
  const EvaluatedClasses ec = load_evaluated_classes(scene, taxonomy, options);
  const std::vector<fs::path> dirs = label_map_dirs(scene, options.labels_dir);
  // Each pixel takes its finest level's class among the evaluated ones (a window pixel scores as window
  // when windows are evaluated, as its wall otherwise); no evaluated class at any level = no prediction.
  const Predict2d predict = [&](const SceneView& v, size_t i, nlohmann::json&) {
    const int H = v.camera.height, W = v.camera.width;
    std::vector<int32_t> pred(size_t(H) * W, -1);
    for (int l = 3; l >= 1; --l) {
      const cv::Mat m = read_label_png(dirs[i] / ("level" + std::to_string(l) + ".png"), CV_16UC1, H, W);
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
          if (const int32_t c = ec.to_eval(int32_t(m.at<uint16_t>(y, x)) - 1); c >= 0) pred[size_t(y) * W + x] = c;
    }
    return std::vector<std::vector<int32_t>>{pred};
  };
  nlohmann::json result = evaluate_2d(scene, ec, options, predict, nullptr);
  result.update(common_json(ec, options));
  result["method"] = "city model labels";
  result["reference"] = true;
  return result;
}

std::string evaluation_tables_markdown(const std::vector<std::pair<std::string, nlohmann::json>>& methods) {
  return tables_markdown(evaluation_tables(methods));
}

}  // namespace cls

namespace cls {

std::string write_evaluation(const std::filesystem::path& out_dir,
                             const std::vector<std::pair<std::string, nlohmann::json>>& methods,
                             const std::string& scene, const std::string& gt_points, const std::string& warning) {
  nlohmann::json results = nlohmann::json::object(), order = nlohmann::json::array();
  for (const auto& [name, r] : methods) {
    results[name] = r;
    order.push_back(name);
  }
  nlohmann::json all = {{"methods", order}, {"results", results}};
  if (!warning.empty()) all["warning"] = warning;
  std::string md = "# Evaluation\n\nScene: " + scene + "; GT: " + gt_points + "\n\n";
  if (!warning.empty()) md += "> " + warning + "\n\n";
  md += evaluation_tables_markdown(methods);
  std::filesystem::create_directories(out_dir);
  write_text_atomic(out_dir / "eval.json", all.dump(2) + "\n");
  write_text_atomic(out_dir / "eval.md", md);
  return md;
}

}  // namespace cls
