// citylangsplat autoencoder: train the shared autoencoder (paper 3.2) on the SAM features of a
// features directory.
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/strings.h"
#include "language/autoencoder_stage.h"

namespace cls {
namespace {

std::string join(const std::vector<int>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
  return s;
}

std::vector<int> parse_dims(const std::string& option, const std::string& text) {
  std::vector<int> dims;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    size_t used = 0;
    int d = 0;
    try {
      d = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || d <= 0)
      throw UsageError("autoencoder: --" + option + " must be a comma-separated list of positive sizes, got '" +
                       text + "'");
    dims.push_back(d);
  }
  if (dims.empty()) throw UsageError("autoencoder: --" + option + " must not be empty");
  return dims;
}

}  // namespace

int cmd_autoencoder(int argc, char** argv) {
  const AutoencoderConfig dc;
  const AutoencoderTrainOptions dt;
  Args args("autoencoder",
            "Train the shared autoencoder (paper 3.2) on the SAM CLIP features of a features directory: every "
            "*_f.npy under DIR (N x 512; the CityGML *_gml_f.npy files are not used for training). Loss "
            "||f - f^||^2 + lambda_cos (1 - cos(f, f^)) per feature; Adam on shuffled mini-batches. Writes the "
            "model (safetensors, config in its metadata) and FILE.json (samples, loss, held-out cosine, seconds).");
  args.option("features", "", "features directory (the features stage's output; required)")
      .option("out", "", "the model file to write, e.g. OUT/autoencoder.safetensors (required)")
      .option("epochs", std::to_string(dt.epochs), "training epochs")
      .option("batch-size", std::to_string(dt.batch_size), "mini-batch size (>= 2)")
      .option("lr", format_number(dt.lr), "Adam learning rate")
      .option("lambda-cos", format_number(dt.lambda_cos), "weight of the cosine term")
      .option("holdout", format_number(dt.holdout_fraction), "fraction of features held out for the reported cosine")
      .option("encoder-dims", join(dc.encoder_dims), "encoder layer sizes after the input; the last is the latent")
      .option("decoder-dims", join(dc.decoder_dims), "decoder layer sizes; the last must be the feature size")
      .option("seed", std::to_string(dt.seed), "seed of initialisation, split and shuffling")
      .option("preset", "", "langsplat: LangSplat's published autoencoder (the langsplat-original baseline): sizes "
                            "256,128,64,32,3 / 16,32,64,128,256,256,512, normalised output, lr 1e-4, batch 64, "
                            "lambda-cos 0.512; combines with --epochs, --holdout and --seed only");
  if (!args.parse(argc, argv)) return 0;
  if (!args.has("features")) throw UsageError("autoencoder: --features is required (see --help)");
  if (!args.has("out")) throw UsageError("autoencoder: --out is required (see --help)");

  AutoencoderStageOptions o;
  o.features_dirs = {args.get("features")};
  o.out = args.get("out");
  o.config.encoder_dims = parse_dims("encoder-dims", args.get("encoder-dims"));
  o.config.decoder_dims = parse_dims("decoder-dims", args.get("decoder-dims"));
  o.config.input_dim = o.config.decoder_dims.back();
  o.train.epochs = args.get_int("epochs");
  o.train.batch_size = args.get_int("batch-size");
  o.train.lr = args.get_double("lr");
  o.train.lambda_cos = args.get_double("lambda-cos");
  o.train.holdout_fraction = args.get_double("holdout");
  const int seed = args.get_int("seed");
  if (seed < 0) throw UsageError("autoencoder: --seed must be >= 0");
  o.train.seed = static_cast<uint64_t>(seed);
  if (args.has("preset")) {
    if (args.get("preset") != "langsplat")
      throw UsageError("autoencoder: --preset takes 'langsplat', got '" + args.get("preset") + "'");
    const std::pair<const char*, std::string> defaults[] = {
        {"batch-size", std::to_string(dt.batch_size)}, {"lr", format_number(dt.lr)},
        {"lambda-cos", format_number(dt.lambda_cos)},  {"encoder-dims", join(dc.encoder_dims)},
        {"decoder-dims", join(dc.decoder_dims)}};
    for (const auto& [option, value] : defaults)
      if (args.get(option) != value) throw UsageError(std::string("autoencoder: --preset sets --") + option + " itself");
    const AutoencoderTrainOptions preset = langsplat_autoencoder_training();
    o.config = langsplat_autoencoder_config();
    o.train.batch_size = preset.batch_size;
    o.train.lr = preset.lr;
    o.train.lambda_cos = preset.lambda_cos;
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
