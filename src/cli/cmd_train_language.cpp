// citylangsplat train-language --scene DIR --model PLY --features DIR --autoencoder FILE --out DIR
// Language training (paper 3.3) on a frozen photometric model; see src/language/language_training.h.
#include <cstdio>
#include <string>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "language/language_training.h"
#include "scene/scene.h"

namespace cls {

int cmd_train_language(int argc, char** argv) {
  const LanguageTrainOptions d;
  Args args("train-language",
            "Train the language field (one latent per Gaussian and level 1-3) on a frozen photometric model under "
            "the coverage-aware SAM + CityGML loss (paper 3.3), or LangSplat's objective with --baseline langsplat.");
  args.option("scene", "", "scene directory (COLMAP or Pix4D) the features were computed for")
      .option("model", "", "photometric model: train-rgb's point_cloud.ply or any 3DGS PLY (geometry stays frozen)")
      .option("features", "", "features stage output directory (per-view *_s.npy / *_f.npy / *_gml_*.npy)")
      .option("autoencoder", "", "the shared autoencoder (train-autoencoder output, .safetensors)")
      .option("out", "", "output model directory (model.json, point_cloud.ply, latents, autoencoder, checkpoints/)")
      .option("iterations", std::to_string(d.iterations), "iterations per level")
      .option("lr", "0.0025", "Adam learning rate of the latents (LangSplat's)")
      .option("lambda-sam", "1.0", "weight of the SAM term inside CityGML coverage")
      .option("lambda-citygml", "0.5", "weight of the CityGML term inside coverage")
      .option("baseline", "", "'langsplat': LangSplat's objective (plain L1 to the SAM targets, no CityGML term); "
                              "'langsplat-original': the same with LangSplat's normalised splatting (give it the "
                              "autoencoder of `autoencoder --preset langsplat`)")
      .flag("normalize-latents", "LangSplat's splatting: each Gaussian's latent divided by its norm before it is "
                                 "splatted (default: raw latents; docs/language.md measures both)")
      .option("checkpoint-every", std::to_string(d.checkpoint_every), "iterations between checkpoints (0 = only on interrupt)")
      .flag("resume", "continue from OUT/checkpoints/language.safetensors if present")
      .option("seed", std::to_string(d.seed), "seed of the view order")
      .option("test-every", "8", "leave every this-th view (sorted by name) out of training, as train-rgb: the views "
                                 "`evaluate` scores in 2D (0 = train on all)")
      .option("resolution", "1", "3DGS-style downscaling factor of the scene's images (must match the features)", "r")
      .option("device", d.device, "auto, cpu or cuda");
  if (!args.parse(argc, argv)) return 0;
  for (const char* required : {"scene", "model", "features", "autoencoder", "out"})
    if (!args.has(required)) throw UsageError(std::string("train-language: --") + required + " is required");

  LanguageTrainOptions o;
  o.geometry_ply = args.get("model");
  o.features_dir = args.get("features");
  o.autoencoder_path = args.get("autoencoder");
  o.out_dir = args.get("out");
  o.iterations = args.get_int("iterations");
  o.lr = args.get_double("lr");
  o.lambda_sam = args.get_double("lambda-sam");
  o.lambda_citygml = args.get_double("lambda-citygml");
  const std::string baseline = args.get("baseline");
  if (!baseline.empty() && baseline != "langsplat" && baseline != "langsplat-original")
    throw UsageError("train-language: --baseline takes 'langsplat' or 'langsplat-original', got '" + baseline + "'");
  o.baseline = !baseline.empty();
  o.normalize_latents = args.flag_set("normalize-latents") || baseline == "langsplat-original";
  o.checkpoint_every = args.get_int("checkpoint-every");
  o.resume = args.flag_set("resume");
  o.seed = static_cast<uint64_t>(args.get_int("seed"));
  o.test_every = args.get_int("test-every");
  if (o.test_every < 0) throw UsageError("train-language: --test-every must be >= 0");
  o.device = args.get("device");

  SceneOptions so;
  so.resolution_factor = args.get_int("resolution");
  so.check_images = false;  // training reads only cameras and features, never the images
  const Scene scene = load_scene(args.get("scene"), so);

  const LanguageTrainReport r = train_language(scene, o);
  if (r.interrupted) {
    std::fprintf(stderr,
                 "interrupted: checkpoint in %s/checkpoints/language.safetensors; resume with the same command and "
                 "--resume\n",
                 o.out_dir.c_str());
    return kInterruptedExit;
  }
  log_info(cat("language model written to ", o.out_dir, " (", r.iterations, " iterations in ", r.seconds,
               " s; final loss per level ", r.final_loss[0], ", ", r.final_loss[1], ", ", r.final_loss[2], ")"));
  return 0;
}

}  // namespace cls
