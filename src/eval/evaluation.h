#pragma once
// The paper's evaluation (section 4): 2D against ground-truth label images projected from a labelled
// point cloud, 3D by nearest-neighbour matching of Gaussian centres; tables in the paper's format.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "citymodel/taxonomy.h"
#include "features/feature_provider.h"
#include "language/language_model.h"
#include "scene/scene.h"

namespace cls {

struct EvaluationOptions {
  std::string gt_points;          // labelled PLY (x y z + int "class" = taxonomy id, -1 = unlabelled)
  std::vector<std::string> classes;  // evaluated class names; empty = every class present in the GT
  double threshold_2d = 0.3;      // pixels whose best normalised relevance is below are ignored
  double match_radius = 0.2;      // 3D nearest-neighbour radius (scene units)
  std::string out_dir;            // eval.json, eval.md, per-view GT/prediction PNGs
};

// One method's scores; the JSON has the paper's table fields (2D: miou, wiou, accuracy, coverage,
// per_class {iou, precision, recall}; 3D: miou, wiou, coverage, mean_distance).
nlohmann::json evaluate_model(const Scene& scene, const LanguageModel& model, FeatureProvider& provider,
                              const Taxonomy& taxonomy, const EvaluationOptions& options);

// The paper's Tables 1-3 side by side for several methods (name -> evaluate_model's JSON), Markdown.
std::string evaluation_tables_markdown(const std::vector<std::pair<std::string, nlohmann::json>>& methods);

}  // namespace cls
