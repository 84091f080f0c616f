#pragma once
// Language training (paper 3.3): geometry frozen, one latent per Gaussian and level, trained under
//   L = sum (1 - M) |Z^ - Z_SAM|_1 + lambda_sam sum M |Z^ - Z_SAM|_1 + lambda_citygml sum M |Z^ - Z_GML|_1
// (SAM terms only where a SAM segment exists, the CityGML term only where C^l is valid).
// `baseline` = LangSplat's objective (the CityGML term dropped: |Z^ - Z_SAM|_1 everywhere). The sparse field
// takes the same terms in CLIP space with --sparse-distance: 1 - cos (sparse_loss.h) or the L1.
#include <cstdint>
#include <string>

#include "core/option_list.h"
#include "language/autoencoder.h"
#include "scene/scene.h"

namespace cls {

struct LanguageTrainOptions {
  std::string geometry_ply;     // photometric model (train-rgb output or any 3DGS PLY)
  std::string features_dir;     // features stage output
  std::string autoencoder_path;
  std::string out_dir;          // language_model.h layout, checkpoints under out_dir/checkpoints
  int iterations = 30000;       // per level
  double lr = 0.0025;           // LangSplat's language feature lr
  double lambda_sam = 1.0, lambda_citygml = 0.5;
  bool baseline = false;        // --baseline langsplat
  // LangSplat's splatting: each Gaussian's latent divided by its norm (+1e-9) before it is splatted; the
  // saved model holds the normalised latents, so every consumer splats and decodes what training did.
  bool normalize_latents = false;
  // The field: "dense" (a latent per Gaussian and level, decoded by the autoencoder) or "sparse"
  // (sparse_field.h: top_k softmax weights over codebook_size bases in CLIP space, per level; no
  // autoencoder). The sparse field's loss compares the rendered features with the CLIP targets themselves,
  // the space both are defined in (the autoencoder is not needed to train or read it).
  std::string field = "dense";
  int codebook_size = 64;
  int top_k = 4;
  double logit_lr = 0.01;       // Adam lr of the sparse field's logits (`lr`: the dense field's latents)
  double codebook_lr = 0.0025;  // Adam lr of the sparse field's codebook
  double sparse_warmup = 0.3;   // share of a level's iterations splatting the softmax over all bases
  // The sparse field's first logits: each basis's mean cosine with the targets a Gaussian is blended into
  // over the training views, divided by this temperature; 0 = seeded noise near zero (no lifting).
  double lift_temperature = 0.1;
  // The sparse field's distance to the targets in the paper's loss: "cosine" (sparse_loss.h: 1 - cos, exact in
  // the L-d weight space; LangSplatV2's) or "l1" (the paper's |.|_1 on the D-d features). docs/language.md
  // measures both.
  std::string sparse_distance = "cosine";
  int checkpoint_every = 1000;
  bool resume = false;
  uint64_t seed = 1;
  // Views left out of training: every test_every-th by name (train-rgb's split, whose held-out views the
  // 2D evaluation scores); 0 = every view trains.
  int test_every = 0;
  std::string device = "auto";  // "auto" (CUDA when the build and machine have it), "cpu", "cuda"
  // CPU: memory (MiB) for the frozen Gaussians' blend weights, kept per view (rasterize.h's BlendCache): a view's
  // first iteration records them, its later ones (all levels) read them instead of blending. At most a quarter
  // of the machine's memory. Views whose weights no longer fit blend every iteration; 0: every view does. The
  // results are the same either way (within float rounding).
  int blend_cache_mb = 4096;
  // Stop as if interrupted (checkpoint, report.interrupted) once this many iterations have run in
  // total over all levels, counting those before a resume; 0 = never. For tests and time budgets.
  int64_t stop_after = 0;
};

struct LanguageTrainReport {
  int iterations = 0;
  double seconds = 0;
  double final_loss[3] = {0, 0, 0};
  bool interrupted = false;  // stopped by a signal after writing a checkpoint
};

// The options of `train-language`, declared once; their settings make run's fingerprint of the stage.
const OptionList<LanguageTrainOptions>& language_train_options();

LanguageTrainReport train_language(const Scene& scene, const LanguageTrainOptions& options);

}  // namespace cls
