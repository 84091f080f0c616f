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
  Args args("train-language",
            "Train the language field (one latent per Gaussian and level 1-3) on a frozen photometric model under "
            "the coverage-aware SAM + CityGML loss (paper 3.3), or LangSplat's objective with --baseline langsplat.");
  std::string scene_dir, baseline;
  int resolution = 1;
  LanguageTrainOptions o;
  o.test_every = 8;  // train-rgb's split
  args.bind("scene", scene_dir, "scene directory (COLMAP, OPF or Pix4D) the features were computed for").required();
  language_train_options().declare(args, o);
  args.bind("baseline", baseline,
            "'langsplat': LangSplat's objective (the SAM targets alone, no CityGML term; L1, or the sparse field's "
            "--sparse-distance); "
            "'langsplat-original': the same with LangSplat's normalised splatting (give it the autoencoder of "
            "`autoencoder --preset langsplat`)",
            choice_codec({"", "langsplat", "langsplat-original"}))
      .bind("resolution", resolution, "3DGS-style downscaling factor of the scene's images (must match the features)")
      .short_name("r");
  if (!args.parse(argc, argv)) return 0;
  language_train_options().apply(args, o);
  o.baseline = !baseline.empty();
  if (baseline == "langsplat-original") o.normalize_latents = true;
  if (o.test_every < 0) throw UsageError("train-language: --test-every must be >= 0");

  SceneOptions so;
  so.resolution_factor = resolution;
  so.check_images = false;  // training reads only cameras and features, never the images
  const Scene scene = load_scene(scene_dir, so);

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
