// citylangsplat autoencoder: train the shared autoencoder (paper 3.2) on the SAM features of a
// features directory.
#include <string>
#include <utility>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "language/autoencoder_stage.h"

namespace cls {

int cmd_autoencoder(int argc, char** argv) {
  Args args("autoencoder",
            "Train the shared autoencoder (paper 3.2) on the SAM CLIP features of a features directory: every "
            "*_f.npy under DIR (N x 512; the CityGML *_gml_f.npy files are not used for training). Loss "
            "||f - f^||^2 + lambda_cos (1 - cos(f, f^)) per feature; Adam on shuffled mini-batches. Writes the "
            "model (safetensors, config in its metadata) and FILE.json (samples, loss, held-out cosine, seconds).");
  AutoencoderStageOptions o;
  std::string preset;
  autoencoder_options().declare(args, o);
  args.bind("preset", preset,
            "langsplat: LangSplat's published autoencoder (the langsplat-original baseline): sizes "
            "256,128,64,32,3 / 16,32,64,128,256,256,512, normalised output, lr 7e-4 (its published command), batch 64, lambda-cos 0.512; "
            "combines with --epochs, --holdout and --seed only",
            choice_codec({"", "langsplat"}));
  if (!args.parse(argc, argv)) return 0;
  autoencoder_options().apply(args, o);
  o.config.input_dim = o.config.decoder_dims.back();
  if (preset == "langsplat") {
    // The preset sets these itself: a value other than the default is a conflict.
    const AutoencoderStageOptions d;
    const std::pair<const char*, bool> changed[] = {{"batch-size", o.train.batch_size != d.train.batch_size},
                                                     {"lr", o.train.lr != d.train.lr},
                                                     {"lambda-cos", o.train.lambda_cos != d.train.lambda_cos},
                                                     {"encoder-dims", o.config.encoder_dims != d.config.encoder_dims},
                                                     {"decoder-dims", o.config.decoder_dims != d.config.decoder_dims}};
    for (const auto& [option, differs] : changed)
      if (differs) throw UsageError(std::string("autoencoder: --preset sets --") + option + " itself");
    const AutoencoderTrainOptions p = langsplat_autoencoder_training();
    o.config = langsplat_autoencoder_config();
    o.train.batch_size = p.batch_size;
    o.train.lr = p.lr;
    o.train.lambda_cos = p.lambda_cos;
  }
  if (o.train.epochs < 1) throw UsageError("autoencoder: --epochs must be >= 1");
  if (o.train.batch_size < 2) throw UsageError("autoencoder: --batch-size must be >= 2");
  if (!(o.train.lr > 0)) throw UsageError("autoencoder: --lr must be positive");
  if (!(o.train.lambda_cos >= 0)) throw UsageError("autoencoder: --lambda-cos must be >= 0");
  if (!(o.train.holdout_fraction >= 0 && o.train.holdout_fraction < 1))
    throw UsageError("autoencoder: --holdout must lie in [0, 1)");
  run_autoencoder_stage(o);
  return 0;
}

}  // namespace cls
