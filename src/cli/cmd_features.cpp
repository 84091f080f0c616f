// citylangsplat features: per-view SAM and CityGML features in LangSplat's layout (paper 3.1-3.2).
#include <filesystem>
#include <string>

#include "core/args.h"
#include "cli/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "features/feature_provider.h"
#include "features/feature_stage.h"
#include "raycast/label_map_io.h"
#include "scene/scene.h"

namespace cls {
namespace fs = std::filesystem;

int cmd_features(int argc, char** argv) {
  Args args("features",
            "Per-view language features (paper 3.1-3.2), in LangSplat's layout: OUT/<stem>_s.npy (SAM seg maps "
            "4 x H x W: default, s, m, l) and _f.npy (one feature per SAM segment), plus the CityGML branch "
            "_gml_s.npy (region ids per level 1-3), _gml_f.npy (fused (1 - alpha) f_gml + alpha f_txt, "
            "normalised) and _gml.json. Views already computed with the same inputs are skipped; "
            "OUT/features.json is written last.");
  args.option("scene", "", "scene directory (COLMAP or Pix4D; required)")
      .option("labels", "", "label map directory of `citylangsplat raycast` (required)")
      .option("out", "", "output directory (required)")
      .option("provider", "clip", "feature source: clip (real CLIP + SAM weights), clip-tiny (tiny random "
                                  "models: a smoke test, results meaningless), synthetic (deterministic "
                                  "stand-in for tests and the mechanics benchmark) or image-segments (segments "
                                  "of the images, features from the ground truth under them: robustness benchmark)")
      .option("gt", "", "image-segments: ground-truth label images named as the views (default: SCENE/gt/labels)")
      .option("alpha", "0.5", "text-guidance weight alpha of the fusion, in [0, 1]")
      .option("regions", "class", "CityGML regions: class (one per level and class, the paper) or instance "
                                  "(one per connected object within a building)")
      .option("min-region-pixels", "16", "skip CityGML regions smaller than this")
      .option("resolution", "1", "divide the image size by 1, 2, 4 or 8 (as for raycast)", "r")
      .option("taxonomy", "", "taxonomy JSON (default: the built-in one); must match the label maps")
      .option("seed", "1", "seed of the synthetic, image-segments and clip-tiny providers")
      .option("clip", "", "CLIP weight file (default: found in the model directories)")
      .option("sam", "", "SAM weight file (default: found in the model directories)")
      .option("clip-model", "openclip-vit-b-16-laion2b", "which known CLIP model (see `models list`)")
      .option("sam-model", "sam-vit-h", "which known SAM model (see `models list`)")
      .option("device", "auto", "clip / clip-tiny: auto (CUDA where available), cpu or cuda")
      .option("models-dir", "", "directory searched first for weights (then $CITYLANGSPLAT_MODELS, the XDG cache)")
      .flag("overwrite", "recompute every view, cached or not");
  if (!args.parse(argc, argv)) return 0;
  for (const char* required : {"scene", "labels", "out"})
    if (!args.has(required)) throw UsageError(std::string("features: --") + required + " is required (see --help)");

  FeatureStageOptions options;
  options.labels_dir = args.get("labels");
  options.out_dir = args.get("out");
  options.alpha = args.get_double("alpha");
  if (!(options.alpha >= 0 && options.alpha <= 1)) throw UsageError("features: --alpha must be in [0, 1]");
  const std::string mode = args.get("regions");
  if (mode == "class") options.region_mode = RegionMode::Class;
  else if (mode == "instance") options.region_mode = RegionMode::Instance;
  else throw UsageError("features: --regions must be class or instance, not '" + mode + "'");
  options.min_region_pixels = args.get_int("min-region-pixels");
  options.overwrite = args.flag_set("overwrite");
  const int factor = args.get_int("resolution");
  if (factor != 1 && factor != 2 && factor != 4 && factor != 8)
    throw UsageError("features: --resolution must be 1, 2, 4 or 8");

  const std::string provider_name = args.get("provider");
  nlohmann::json spec = {{"provider", provider_name}};
  if (provider_name == "synthetic" || provider_name == "clip-tiny" || provider_name == "image-segments") {
    spec["seed"] = static_cast<uint64_t>(args.get_int("seed"));
    if (provider_name == "clip-tiny") spec["device"] = args.get("device");
    if (provider_name == "image-segments")
      spec["gt"] = args.has("gt") ? args.get("gt") : (fs::path(args.get("scene")) / "gt" / "labels").string();
  } else if (provider_name == "clip") {
    spec["device"] = args.get("device");
    if (args.has("clip")) spec["clip"] = args.get("clip");
    if (args.has("sam")) spec["sam"] = args.get("sam");
    spec["clip_model"] = args.get("clip-model");
    spec["sam_model"] = args.get("sam-model");
    if (args.has("models-dir")) spec["models_dir"] = args.get("models-dir");
  } else {
    throw UsageError("features: unknown --provider '" + provider_name + "' (clip, clip-tiny, synthetic or image-segments)");
  }

  // Inputs first, then the (possibly slow) models.
  const Taxonomy taxonomy = args.has("taxonomy") ? Taxonomy::load(args.get("taxonomy")) : Taxonomy::builtin();
  if (!fs::is_directory(options.labels_dir))
    fail(options.labels_dir.string(), "label map directory not found (make it with `citylangsplat raycast`)");
  check_label_legend(options.labels_dir, taxonomy);
  SceneOptions scene_options;
  scene_options.resolution_factor = factor;
  const Scene scene = load_scene(args.get("scene"), scene_options);
  if (scene.views.empty()) fail(args.get("scene"), "the scene has no views");

  const auto provider = make_feature_provider(spec, taxonomy);
  if (provider->name() == "clip-tiny") log_warn("features: clip-tiny uses tiny random models: results are meaningless");
  const int computed = run_feature_stage(scene, *provider, taxonomy, options);
  log_info(cat("features: computed ", computed, " of ", scene.views.size(), " views into ", options.out_dir.string()));
  return 0;
}

}  // namespace cls
