#pragma once
// The autoencoder stage (`citylangsplat autoencoder`, paper 3.2): collect the SAM CLIP features of a
// features directory (every <stem>_f.npy, never the CityGML <stem>_gml_f.npy: the autoencoder is
// trained on SAM features only), train, write the model and a JSON report.
#include <ATen/core/Tensor.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/option_list.h"
#include "language/autoencoder.h"

namespace cls {

// Every *_f.npy under `dir` (recursively) that is not a *_gml_f.npy, sorted by path. cls::Error when
// `dir` is not a directory.
std::vector<std::filesystem::path> find_sam_feature_files(const std::filesystem::path& dir);
// The same over several directories (one per tile), sorted by a file's path within its directory. A path
// found in several (an image in two tiles, whose features are the same in both) is taken once, from the
// first: tiles that share images train on the pool one run of the whole district would. cls::Error for a
// directory without any.
std::vector<std::filesystem::path> find_sam_feature_files(const std::vector<std::filesystem::path>& dirs);

// The rows of all files stacked (float32, sum N x input_dim); with max_samples > 0 and more rows than
// that, a uniform random sample of max_samples rows (reservoir sampling, seeded: one file in memory at a
// time, whatever the total). `rows_read` (optional) gets the total. cls::Error naming the file for an
// unreadable file, a shape other than N x input_dim, a non-float dtype or NaN/infinite values.
at::Tensor read_sam_features(const std::vector<std::filesystem::path>& files, int input_dim, int64_t max_samples = 0,
                             uint64_t seed = 0, int64_t* rows_read = nullptr);

struct AutoencoderStageOptions {
  // One features directory, or one per tile (a shared autoencoder: docs/scale.md): find_sam_feature_files.
  std::vector<std::filesystem::path> features_dirs;
  // Train on at most this many rows, a uniform sample (train.seed) of all of them; 0 = every row.
  int64_t max_samples = 0;
  std::filesystem::path out;  // the model (safetensors); the report goes to <out>.json
  AutoencoderConfig config;
  AutoencoderTrainOptions train;  // train.seed also seeds the initialisation
};

// The options of `autoencoder`, declared once (one features directory; input_dim follows decoder-dims);
// their settings make run's fingerprint of the stage.
const OptionList<AutoencoderStageOptions>& autoencoder_options();

// Reads every directory, keeps max_samples rows, trains (progress per epoch), writes `out` atomically and then `out`.json:
// {"samples", "rows_read", "train_samples", "holdout_samples", "files", "train_loss", "holdout_cosine" (null when
// nothing was held out), "seconds", "epochs", "batch_size", "lr", "lambda_cos", "holdout_fraction",
// "seed", "config"}. cls::Error when there are no feature files or no feature rows.
AutoencoderReport run_autoencoder_stage(const AutoencoderStageOptions& options);

}  // namespace cls
