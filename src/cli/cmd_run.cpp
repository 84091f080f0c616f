// citylangsplat run: the CLI over src/pipeline (pipeline.h has the stage order): options and the
// scene's scene.json -> PipelineConfig -> run_pipeline -> exit status.
#include <cstdio>
#include <filesystem>
#include <string>

#include "citymodel/city_model.h"
#include "cli/city_mesh_inputs.h"
#include "cli/commands.h"
#include "core/args.h"
#include "core/strings.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "pipeline/pipeline.h"

namespace cls {
namespace fs = std::filesystem;

int cmd_run(int argc, char** argv) {
  Args args("run",
            std::string("Run every stage on a scene directory (COLMAP or Pix4D, images under SCENE/images), reusing "
                        "stages whose inputs have not changed: label maps, features, autoencoder, photometric 3DGS, "
                        "the language fields of CityLangSplat and of the LangSplat baseline, queries for the "
                        "taxonomy's classes and, when SCENE/gt/points.ply exists, the evaluation. The city model "
                        "comes from --config FILE or SCENE/scene.json (keys city_model, city_transform, taxonomy, "
                        "lod; paths relative to the file), or from the options below, which override the file. "
                        "--models auto uses CLIP and SAM weights where `citylangsplat models list` finds both and "
                        "synthetic features otherwise (said on the terminal, in run.json and in the report); "
                        "--models real stops before the features when the weights are missing. ") +
                kExitCodesHelp + ".");
  args.positional("SCENE_DIR", "scene directory");
  add_scene_city_options(args);
  args.option("out", "", "output directory (default: SCENE_DIR/citylangsplat)")
      .option("resolution", "1", "divide the image size by 1, 2, 4 or 8", "r")
      .option("align-distance", "0.5", "alignment check: distance threshold in city-model metres")
      .option("align", "auto",
              "refine the city transform from the sparse points before raycasting (as `align`): refine, off, or "
              "auto (refine, and use it when it moves the model by more than 5 cm)")
      .option("models", "auto",
              "auto (real where the weights are found, else synthetic), real (CLIP + SAM weights), tiny (tiny "
              "random models: smoke test), synthetic (synthetic features: mechanics benchmark) or image-segments "
              "(segments of the images, features from SCENE/gt/labels: robustness benchmark)")
      .option("clip", "", "CLIP weights file (default: searched, see `models list`)")
      .option("sam", "", "SAM weights file (default: searched, see `models list`)")
      .option("alpha", "0.5", "text-guidance weight of the CityGML features")
      .option("regions", "class", "CityGML regions: class (one per class and view) or instance")
      .option("rgb-model", "", "import this 3DGS PLY instead of training the photometric model")
      .option("rgb-iterations", "", "photometric iterations (default: real 30000; tiny 100; synthetic 1500)")
      .option("language-iterations", "",
              "language iterations per level (default: real 30000; tiny 20; synthetic 300)")
      .option("autoencoder-epochs", "", "autoencoder epochs (default: real 100; tiny 5; synthetic 40)")
      .option("lambda-sam", "1.0", "weight of the SAM term in covered pixels")
      .option("lambda-citygml", "0.5", "weight of the CityGML term")
      .option("autoencoder", "",
              "use this autoencoder (e.g. the one shared by all tiles, docs/scale.md) instead of training one")
      .option("stop-after", "", "features: stop after the features stage (tiles train a shared autoencoder next)")
      .option("baseline", "langsplat",
              "baselines beside CityLangSplat, comma-separated: langsplat (LangSplat's objective on the shared "
              "autoencoder), langsplat-original (LangSplat as published: its 3-d autoencoder and settings, "
              "normalised splatting), or none")
      .flag("no-baseline", "no baseline (= --baseline none)");
  if (!args.parse(argc, argv)) return kExitOk;

  PipelineConfig c;
  c.scene_dir = args.get("SCENE_DIR");
  c.out_dir = args.has("out") ? fs::path(args.get("out")) : c.scene_dir / "citylangsplat";
  read_scene_city_options(args, c.scene_dir, c);
  c.resolution = args.get_int("resolution");
  c.align_distance = args.get_double("align-distance");
  c.align = args.get("align");
  c.models = parse_models_choice(args.get("models"));
  c.clip_weights = args.get("clip");
  c.sam_weights = args.get("sam");
  c.alpha = args.get_double("alpha");
  c.regions = args.get("regions");
  c.rgb_model = args.get("rgb-model");
  for (const auto& [option, into] : {std::pair{"rgb-iterations", &c.rgb_iterations},
                                     std::pair{"language-iterations", &c.language_iterations},
                                     std::pair{"autoencoder-epochs", &c.autoencoder_epochs}}) {
    if (!args.has(option)) continue;
    *into = args.get_int(option);
    if (*into < 1) throw UsageError(std::string("run: --") + option + " must be >= 1");
  }
  c.lambda_sam = args.get_double("lambda-sam");
  c.lambda_citygml = args.get_double("lambda-citygml");
  c.baseline = false;
  for (const std::string& b : split_commas(args.flag_set("no-baseline") ? "none" : args.get("baseline"))) {
    if (b == "langsplat")
      c.baseline = true;
    else if (b == "langsplat-original")
      c.baseline_original = true;
    else if (b != "none")
      throw UsageError("run: --baseline takes langsplat, langsplat-original or none, got '" + b + "'");
  }
  c.autoencoder = args.get("autoencoder");
  if (args.has("stop-after") && args.get("stop-after") != "features")
    throw UsageError("run: --stop-after takes only 'features', got '" + args.get("stop-after") + "'");
  c.stop_after_features = args.has("stop-after");

  const PipelineResult r = run_pipeline(c);
  if (r.outcome == PipelineOutcome::MissingWeights)
    std::fprintf(stderr, "run: stopped before the features (exit %d): %s\nResults so far: %s\n",
                 kExitMissingWeights, r.message.c_str(), r.run_json.string().c_str());
  std::printf("Report: %s\n", r.report.string().c_str());
  return exit_code(r.outcome);
}

}  // namespace cls
