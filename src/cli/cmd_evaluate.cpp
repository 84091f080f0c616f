// citylangsplat evaluate --scene DIR --gt PLY --model NAME=DIR [--model NAME=DIR ...] --out DIR
// The paper's evaluation (section 4) of one or more language models against a labelled point cloud,
// with the same prototypes for every model; OUT/eval.json, OUT/eval.md, OUT/<NAME>/views/*.png.
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/args.h"
#include "cli/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/strings.h"
#include "core/log.h"
#include "eval/evaluation.h"
#include "features/feature_provider.h"
#include "language/language_model.h"
#include "raycast/label_map_io.h"
#include "scene/scene.h"

namespace fs = std::filesystem;

namespace cls {
namespace {

nlohmann::json provider_spec(const std::string& text) {
  const std::string json = fs::exists(text) ? read_text_file(text) : text;
  try {
    return nlohmann::json::parse(json);
  } catch (const nlohmann::json::exception& e) {
    throw UsageError("evaluate: --provider is neither a JSON spec nor a readable JSON file: " + std::string(e.what()));
  }
}

}  // namespace

int cmd_evaluate(int argc, char** argv) {
  // --model may repeat: collect its values before the common parser sees the rest.
  std::vector<std::pair<std::string, std::string>> models;
  std::vector<std::string> rest;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i], value;
    if (a == "--model") {
      if (i + 1 >= argc) throw UsageError("evaluate: --model needs NAME=DIR");
      value = argv[++i];
    } else if (a.rfind("--model=", 0) == 0) {
      value = a.substr(8);
    } else {
      rest.push_back(a);
      continue;
    }
    const size_t eq = value.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == value.size())
      throw UsageError("evaluate: --model takes NAME=DIR, got '" + value + "'");
    models.emplace_back(value.substr(0, eq), value.substr(eq + 1));
  }

  Args args("evaluate",
            "Evaluate language models as in the paper (section 4): GT label images projected from a labelled point "
            "cloud (2D: mIoU, wIoU, accuracy, coverage, per-class IoU/precision/recall) and GT points matched to "
            "Gaussian centres (3D: mIoU, wIoU, coverage, mean distance). Writes OUT/eval.json, OUT/eval.md (the "
            "paper's Tables 1-3, methods side by side) and OUT/<NAME>/views/<stem>_{gt,pred}.png.");
  args.option("scene", "", "scene directory (COLMAP / Pix4D)")
      .option("gt", "", "labelled point cloud PLY (x y z + int class = taxonomy id, -1 = none) (default: SCENE/gt/points.ply)")
      .option("gt-class-property", "class", "the GT PLY's integer vertex property with the taxonomy class id")
      .option("model", "", "NAME=DIR of a language model directory; repeat for several methods")
      .option("out", "", "output directory")
      .option("threshold", "0.3", "2D: pixels whose best normalised relevance is below are ignored")
      .option("radius", "0.2", "3D: nearest-neighbour match radius (scene units)")
      .option("level-rule", "fallback", "fallback (level 1 for subpart/part classes, 3 for whole) or langsplat (highest maximum)")
      .option("phrases", "held-out", "a class's prototype: held-out (its prompts but prompts[0], the fusion's class "
              "prompt) or all")
      .option("classes", "", "comma-separated class names to evaluate (default: every class in the GT)")
      .option("provider", "", "feature provider spec, JSON text or file (default: the first model's model.json provider)")
      .option("taxonomy", "", "taxonomy JSON (default: the built-in one)")
      .option("gt-point-radius", "0", "GT projection footprint radius in scene units (0 = from the cloud's spacing)")
      .option("labels", "", "raycast label maps of these views (`citylangsplat raycast` output): adds 2D scores on the GT "
              "the city model covers (M = 1) and the label maps themselves as a reference row")
      .option("resolution", "1", "3DGS-style downscaling factor of the views: 1, 2, 4 or 8", "r")
      .option("test-every", "8", "2D on the held-out views, every this-th by name (as train-rgb and train-language "
                                 "hold them out); the training views apart as \"2d_train\" (0 = every view in \"2d\")")
      .flag("no-images", "do not write the per-view GT/prediction PNGs");
  std::vector<char*> rest_argv{argv[0]};
  for (std::string& s : rest) rest_argv.push_back(s.data());
  if (!args.parse(int(rest_argv.size()), rest_argv.data())) return 0;
  if (!args.has("scene")) throw UsageError("evaluate: --scene is required");
  if (!args.has("out")) throw UsageError("evaluate: --out is required");
  if (models.empty() && !args.has("labels"))
    throw UsageError("evaluate: at least one --model NAME=DIR (or --labels DIR) is required");
  for (size_t i = 0; i < models.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (models[i].first == models[j].first) throw UsageError("evaluate: model name '" + models[i].first + "' given twice");

  const Taxonomy taxonomy = args.has("taxonomy") ? Taxonomy::load(args.get("taxonomy")) : Taxonomy::builtin();
  SceneOptions scene_options;
  scene_options.resolution_factor = args.get_int("resolution");
  const Scene scene = load_scene(args.get("scene"), scene_options);
  EvaluationOptions options;
  options.gt_points = args.has("gt") ? args.get("gt") : (fs::path(args.get("scene")) / "gt" / "points.ply").string();
  options.gt_class_property = args.get("gt-class-property");
  options.classes = split_commas(args.get("classes"));
  options.threshold_2d = args.get_double("threshold");
  options.match_radius = args.get_double("radius");
  options.level_rule = args.get("level-rule");
  options.phrases = args.get("phrases");
  options.gt_point_radius = args.get_double("gt-point-radius");
  options.write_view_images = !args.flag_set("no-images");
  options.test_every = args.get_int("test-every");
  if (options.test_every < 0) throw UsageError("evaluate: --test-every must be >= 0");
  options.labels_dir = args.get("labels");
  if (!options.labels_dir.empty()) {
    if (!fs::is_directory(options.labels_dir))
      fail(options.labels_dir, "--labels: not a directory (the `citylangsplat raycast` output for these views)");
    check_label_legend(options.labels_dir, taxonomy);
    for (const auto& m : models)
      if (m.first == kLabelMapsMethod)
        throw UsageError(std::string("evaluate: the name '") + kLabelMapsMethod + "' is the label maps' row; name the model otherwise");
  }
  const fs::path out = args.get("out");
  fs::create_directories(out);

  // One provider for every method: the prototypes must be the same (paper 4.3).
  std::unique_ptr<FeatureProvider> provider;
  std::vector<std::pair<std::string, nlohmann::json>> results;
  for (const auto& [name, dir] : models) {
    const LanguageModel model = load_language_model(dir);
    if (!provider) {
      nlohmann::json spec;
      if (args.has("provider")) spec = provider_spec(args.get("provider"));
      else if (model.info.contains("provider")) spec = model.info["provider"];
      else throw UsageError("evaluate: " + dir + "/model.json names no feature provider; pass --provider");
      provider = make_feature_provider(spec, taxonomy);
    }
    log_info("evaluate: " + name + " (" + dir + ")");
    options.out_dir = (out / name).string();
    nlohmann::json r = evaluate_model(scene, model, *provider, taxonomy, options);
    log_info(cat("  2D mIoU ", r["2d"]["miou"].get<double>(), ", 3D mIoU ", r["3d"]["miou"].get<double>()));
    results.emplace_back(name, std::move(r));
  }
  if (!options.labels_dir.empty()) {
    log_info("evaluate: " + std::string(kLabelMapsMethod) + " (" + options.labels_dir + ")");
    options.out_dir = (out / kLabelMapsMethod).string();
    results.emplace_back(kLabelMapsMethod, evaluate_label_maps(scene, taxonomy, options));
  }
  const std::string warning = provider ? provider_warning(provider->name()) : "";
  write_evaluation(out, results, args.get("scene"), options.gt_points, warning);
  log_info("evaluate: wrote " + (out / "eval.json").string() + " and " + (out / "eval.md").string());
  return 0;
}

}  // namespace cls
