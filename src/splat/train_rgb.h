#pragma once
// Photometric 3DGS training (Kerbl et al. 2023, the original's defaults): L1 + 0.2 D-SSIM, Adam with
// the original's learning rates (position lr decayed exponentially 1.6e-4 -> 1.6e-6, x scene extent),
// densification (clone / split / prune) every 100 iterations from 500 to 15000, opacity reset every
// 3000, SH degree raised every 1000; initialised from the SfM points. Held-out test views (every
// 8th) give PSNR / SSIM. Checkpoints at an interval and on SIGINT / SIGTERM; resume is exact.
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/option_list.h"
#include "scene/scene.h"

namespace cls {

struct RgbTrainOptions {
  std::string out_dir;               // point_cloud.ply, summary.json, checkpoints/
  int iterations = 30000;
  int sh_degree = 3;
  double position_lr_init = 1.6e-4, position_lr_final = 1.6e-6;
  double feature_lr = 2.5e-3, opacity_lr = 0.05, scaling_lr = 0.005, rotation_lr = 0.001;
  double lambda_dssim = 0.2;
  int densify_from = 500, densify_until = 15000, densify_every = 100;
  double densify_grad_threshold = 0.0002;
  double percent_dense = 0.01;
  int opacity_reset_every = 3000;
  int sh_increase_every = 1000;
  int64_t max_gaussians = 0;         // 0 = no cap
  bool random_background = false;
  bool white_background = false;
  int test_every = 8;                // every 8th view held out; 0 = train on all
  int checkpoint_every = 5000;
  bool resume = false;
  uint64_t seed = 1;
  std::string device = "auto";  // compute_device(): auto (CUDA where built and present), cpu or cuda
};

struct RgbTrainReport {
  int iterations = 0;
  int64_t gaussians = 0;
  double test_psnr = 0, test_ssim = 0;  // mean over held-out views (0 views: train views)
  int test_views = 0;
  double seconds = 0;
  bool interrupted = false;
};

// The options of `train-rgb`, declared once; their settings make run's fingerprint of the stage.
// densify_until -1 on the command line is "auto" (auto_densify_until).
const OptionList<RgbTrainOptions>& rgb_train_options();
// A densification or opacity reset late in a short run leaves too few iterations to train what it
// changed (3,000 iterations with the reset at 3,000 ended at 9.6 dB): 3DGS's 15000 of 30000, at most
// half the iterations.
int auto_densify_until(int iterations);
// Where train-rgb keeps its checkpoint in its output directory (written every checkpoint_every
// iterations, on an interrupt and at the end; `resume` continues from it).
std::filesystem::path rgb_checkpoint(const std::filesystem::path& out_dir);

// The scene's images are read through ImageLoader at the scene's loaded resolution.
RgbTrainReport train_rgb(const Scene& scene, const RgbTrainOptions& options);

}  // namespace cls
