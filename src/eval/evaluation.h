#pragma once
// The paper's evaluation (section 4): 2D against ground-truth label images projected from a labelled
// point cloud, 3D by nearest-neighbour matching of Gaussian centres; tables in the paper's format.
#include <ATen/core/Tensor.h>
#include <filesystem>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "citymodel/taxonomy.h"
#include "features/feature_provider.h"
#include "language/language_model.h"
#include "scene/scene.h"

namespace cls {

struct EvaluationOptions {
  std::string gt_points;          // labelled PLY (x y z + int "class" = taxonomy id, -1 = unlabelled) or LAS
  std::string gt_class_property;  // its label field ("": "class" in a PLY, "classification" in a LAS)
  std::string class_map;          // its label values -> taxonomy classes (eval/class_map.h); "" = taxonomy ids
  std::string gt_images;          // 2D GT as label images, one per photo (eval/gt_images.h), instead of the cloud's
                                  // projection; with no cloud (gt_points "") there are no 3D scores
  std::string gt_transform;       // a city transform JSON moving the GT from the city model's CRS into the scene
                                  // frame (the run's labels/city_transform.json); "" = the GT is in the scene frame
  std::vector<std::string> classes;  // evaluated class names; empty = every class present in the GT
  double threshold_2d = 0.3;      // pixels whose best normalised relevance is below are ignored
  double match_radius = 0.2;      // 3D nearest-neighbour radius (scene units)
  std::string out_dir;            // eval.json, eval.md, per-view GT/prediction PNGs
  // Which level's field answers a class (docs/evaluation.md): "fallback" = level 1 for taxonomy levels 1
  // and 2 (level 1 carries part classes through the subpart fallback), level 3 for level-3 classes;
  // "langsplat" = LangSplat's rule, the level whose raw cosine map (2D: per view; 3D: over all
  // Gaussians) has the highest maximum.
  std::string level_rule = "fallback";
  // The phrases that make a class's prototype: "held-out" = its prompts except prompts[0], the class prompt
  // the text-guided fusion put into the CityGML features (scoring with it would reward the method for the
  // very text it was given; a class with no other prompt keeps prompts[0]); "all" = every prompt.
  std::string phrases = "held-out";
  double gt_point_radius = 0;     // GT projection footprint (scene units); 0 = from the cloud's spacing
  // The raycast label maps (`citylangsplat raycast` output) of these views: when set, 2D is also scored
  // on the GT pixels the city model covers (coverage M = 1, "2d_covered"); evaluate_label_maps needs it.
  std::string labels_dir;
  bool write_view_images = true;  // OUT/views/<stem>_gt.png, <stem>_pred.png (when out_dir is set)
  // 0: "2d" scores every view. N > 0: "2d" (and "2d_covered") score the held-out views, every N-th by name
  // as train-rgb and train-language --test-every hold them out, and "2d_train" the views training saw.
  int test_every = 0;
};

// One method's scores; the JSON has the paper's table fields (2D: miou, wiou, accuracy, coverage,
// per_class {iou, precision, recall}; 3D: miou, wiou, coverage, mean_distance). "2d" reads the plain
// cosine ("relevance": "cosine"); "2d_relevancy" the same views with LangSplat's relevancy instead.
nlohmann::json evaluate_model(const Scene& scene, const LanguageModel& model, FeatureProvider& provider,
                              const Taxonomy& taxonomy, const EvaluationOptions& options);

// The tables' layout version: `run` recomputes an evaluation written by another version.
inline constexpr const char* kEvaluationTables =
    "2026-11-29 held-out phrases, held-out 2D views, 3D Gaussians per class, 2D with LangSplat's relevancy";

// The label maps' row name in the tables.
inline constexpr const char* kLabelMapsMethod = "city-model-labels";

// The label maps themselves as a 2D prediction, scored against the same GT: each pixel takes its finest
// level's class among the evaluated ones; pixels with none are not scored. A reference for what exact
// CityGML labels score against this GT (their alignment, level of detail and the GT projection's own
// errors limit it); not a strict bound for a method, which may gain where the projection errs its way.
// 2D only: no "3d" fields; "reference": true.
nlohmann::json evaluate_label_maps(const Scene& scene, const Taxonomy& taxonomy, const EvaluationOptions& options);

// The class prototypes (paper 4.3): per class the mean of the provider's text features of its phrase
// set (the taxonomy's prompts), normalised: classes.size() x D.
at::Tensor class_prototypes(FeatureProvider& provider, const Taxonomy& taxonomy, const std::vector<int>& classes,
                            const std::string& phrases = "held-out");
// The phrases of one class under that rule (EvaluationOptions::phrases).
std::vector<std::string> evaluation_phrases(const SemanticClass& c, const std::string& phrases);

// The paper's Tables 1-3 side by side for several methods (name -> evaluate_model's JSON), Markdown.
std::string evaluation_tables_markdown(const std::vector<std::pair<std::string, nlohmann::json>>& methods);

// The evaluation's files, the same for `evaluate` and `run` (docs/evaluation.md): OUT/eval.json
// {"methods": [names in order], "results": {name: JSON}, "warning": <text, when not empty>} and OUT/eval.md
// (scene, GT, the warning, the tables). Both atomic; returns the Markdown.
std::string write_evaluation(const std::filesystem::path& out_dir,
                             const std::vector<std::pair<std::string, nlohmann::json>>& methods,
                             const std::string& scene, const std::string& gt_points, const std::string& warning);

}  // namespace cls
