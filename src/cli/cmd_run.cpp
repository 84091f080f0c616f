// citylangsplat run: the CLI over src/pipeline (pipeline.h has the stage order): options (declared once
// in pipeline_options()) and the scene's scene.json -> PipelineConfig -> run_pipeline -> exit status.
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/commands.h"
#include "core/args.h"
#include "core/exit_codes.h"
#include "pipeline/pipeline.h"

namespace cls {

int cmd_run(int argc, char** argv) {
  Args args("run",
            std::string("Run every stage on a scene directory (COLMAP, OPF or Pix4D, images under SCENE/images), reusing "
                        "stages whose inputs have not changed: label maps, features, autoencoder, photometric 3DGS, "
                        "the language fields of CityLangSplat and of the LangSplat baseline, queries for the "
                        "taxonomy's classes and, when SCENE/gt/points.ply exists, the evaluation. The city model "
                        "comes from --config FILE or SCENE/scene.json (keys city_model, city_transform, taxonomy, "
                        "lod; paths relative to the file), or from the options below, which override the file. "
                        "--models auto uses CLIP and SAM weights where `citylangsplat models list` finds both and "
                        "synthetic features otherwise (said on the terminal, in run.json and in the report); "
                        "--models clip stops before the features when the weights are missing. ") +
                kExitCodesHelp + ".");
  std::filesystem::path config_file;
  args.bind("config", config_file, "JSON scene config: city_model, city_transform, taxonomy, lod (paths relative to it)")
      .default_text("SCENE_DIR/scene.json where it exists");
  pipeline_options().declare(args, PipelineConfig{});
  if (!args.parse(argc, argv)) return kExitOk;

  PipelineConfig c;
  pipeline_options().apply(args, c);
  apply_scene_config(args, config_file, c);
  const PipelineResult r = run_pipeline(c);
  if (r.outcome == PipelineOutcome::MissingWeights)
    std::fprintf(stderr, "run: stopped before the features (exit %d): %s\nResults so far: %s\n",
                 kExitMissingWeights, r.message.c_str(), r.run_json.string().c_str());
  std::printf("Report: %s\n", r.report.string().c_str());
  return exit_code(r.outcome);
}

}  // namespace cls
