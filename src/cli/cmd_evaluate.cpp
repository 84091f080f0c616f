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
#include "core/run_layout.h"
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
  std::string scene_dir, out_dir, provider_text, taxonomy_path;
  SceneOptions scene_options;
  EvaluationOptions options;
  options.test_every = 8;
  args.bind("scene", scene_dir, "scene directory (COLMAP / Pix4D)")
      .required()
      .bind("gt", options.gt_points,
            "labelled point cloud: PLY (x y z + int class = taxonomy id, -1 = none) or LAS 1.0-1.4 (with --class-map)")
      .default_text("SCENE/gt/points.ply; none with --gt-images")
      .bind("gt-images", options.gt_images,
            "2D ground truth as label images, DIR/<photo name>.png, one channel of 8 or 16 bits at the photo's size "
            "(taxonomy id + 1, 0 = none, or the --class-map's codes), in place of the cloud's projection; 3D is "
            "scored only with --gt")
      .bind("gt-class-property", options.gt_class_property,
            "the GT's label field: a PLY vertex property, or in a LAS classification or an extra-bytes field")
      .default_text("class in a PLY, classification in a LAS")
      .bind("class-map", options.class_map,
            "JSON mapping the GT's label values to taxonomy classes (data/class-maps/zaha-lofg3.json: ZAHA); without "
            "it the labels are taxonomy ids")
      .bind("gt-transform", options.gt_transform,
            "the GT lies in the city model's CRS: move it into the scene frame by this city transform (a run's "
            "OUT/labels/city_transform.json)")
      // Read above (it repeats); declared for --help.
      .declare("model", "", "NAME=DIR of a language model directory; repeat for several methods", false)
      .bind("out", out_dir, "output directory")
      .required()
      .bind("threshold", options.threshold_2d, "2D: pixels whose best normalised relevance is below are ignored")
      .bind("radius", options.match_radius, "3D: nearest-neighbour match radius (scene units)")
      .bind("level-rule", options.level_rule,
            "fallback (level 1 for subpart/part classes, 3 for whole) or langsplat (highest maximum)")
      .bind("phrases", options.phrases, "a class's prototype: held-out (its prompts but prompts[0], the fusion's class "
                                        "prompt) or all")
      .bind("classes", options.classes, "comma-separated class names to evaluate (default: every class in the GT)")
      .bind("provider", provider_text,
            "feature provider spec, JSON text or file (default: the first model's model.json provider)")
      .bind("taxonomy", taxonomy_path, "taxonomy JSON (default: the built-in one)")
      .bind("gt-point-radius", options.gt_point_radius,
            "GT projection footprint radius in scene units (0 = from the cloud's spacing)")
      .bind("labels", options.labels_dir, "raycast label maps of these views (`citylangsplat raycast` output): adds 2D "
                                          "scores on the GT the city model covers (M = 1) and the label maps themselves "
                                          "as a reference row")
      .bind("resolution", scene_options.resolution_factor, "3DGS-style downscaling factor of the views: 1, 2, 4 or 8")
      .short_name("r")
      .bind("test-every", options.test_every,
            "2D on the held-out views, every this-th by name (as train-rgb and train-language hold them out); the "
            "training views apart as \"2d_train\" (0 = every view in \"2d\")")
      .flag("no-images", options.write_view_images, "do not write the per-view GT/prediction PNGs", false);
  std::vector<char*> rest_argv{argv[0]};
  for (std::string& s : rest) rest_argv.push_back(s.data());
  if (!args.parse(int(rest_argv.size()), rest_argv.data())) return 0;
  if (models.empty() && options.labels_dir.empty())
    throw UsageError("evaluate: at least one --model NAME=DIR (or --labels DIR) is required");
  for (size_t i = 0; i < models.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (models[i].first == models[j].first) throw UsageError("evaluate: model name '" + models[i].first + "' given twice");

  const Taxonomy taxonomy = taxonomy_path.empty() ? Taxonomy::builtin() : Taxonomy::load(taxonomy_path);
  const Scene scene = load_scene(scene_dir, scene_options);
  if (options.gt_points.empty() && options.gt_images.empty()) options.gt_points = SceneFiles{scene_dir}.gt_points().string();
  if (!options.gt_images.empty() && !fs::is_directory(options.gt_images))
    fail(options.gt_images, "--gt-images: not a directory (DIR/<photo name>.png per view)");
  if (options.test_every < 0) throw UsageError("evaluate: --test-every must be >= 0");
  if (!options.labels_dir.empty()) {
    if (!fs::is_directory(options.labels_dir))
      fail(options.labels_dir, "--labels: not a directory (the `citylangsplat raycast` output for these views)");
    check_label_legend(options.labels_dir, taxonomy);
    for (const auto& m : models)
      if (m.first == kLabelMapsMethod)
        throw UsageError(std::string("evaluate: the name '") + kLabelMapsMethod + "' is the label maps' row; name the model otherwise");
  }
  const fs::path out = out_dir;
  fs::create_directories(out);

  // One provider for every method: the prototypes must be the same (paper 4.3).
  std::unique_ptr<FeatureProvider> provider;
  std::vector<std::pair<std::string, nlohmann::json>> results;
  for (const auto& [name, dir] : models) {
    const LanguageModel model = load_language_model(dir);
    if (!provider) {
      nlohmann::json spec;
      if (!provider_text.empty()) spec = provider_spec(provider_text);
      else if (model.info.contains("provider")) spec = model.info["provider"];
      else throw UsageError("evaluate: " + dir + "/model.json names no feature provider; pass --provider");
      provider = make_feature_provider(spec, taxonomy);
    }
    log_info("evaluate: " + name + " (" + dir + ")");
    options.out_dir = (out / name).string();
    nlohmann::json r = evaluate_model(scene, model, *provider, taxonomy, options);
    log_info(cat("  2D mIoU ", r["2d"]["miou"].get<double>(),
                 r.contains("3d") ? cat(", 3D mIoU ", r["3d"]["miou"].get<double>()) : std::string(", no 3D GT")));
    results.emplace_back(name, std::move(r));
  }
  if (!options.labels_dir.empty()) {
    log_info("evaluate: " + std::string(kLabelMapsMethod) + " (" + options.labels_dir + ")");
    options.out_dir = (out / kLabelMapsMethod).string();
    results.emplace_back(kLabelMapsMethod, evaluate_label_maps(scene, taxonomy, options));
  }
  const std::string warning = provider ? provider_warning(provider->name()) : "";
  write_evaluation(out, results, scene_dir, options.gt_points.empty() ? options.gt_images : options.gt_points, warning);
  log_info("evaluate: wrote " + (out / "eval.json").string() + " and " + (out / "eval.md").string());
  return 0;
}

}  // namespace cls
