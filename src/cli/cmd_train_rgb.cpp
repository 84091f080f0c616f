// citylangsplat train-rgb --scene DIR --out DIR [options]: photometric 3DGS training.
#include <cstdio>
#include <string>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "scene/scene.h"
#include "splat/train_rgb.h"

namespace cls {

int cmd_train_rgb(int argc, char** argv) {
  Args args("train-rgb",
            "Train 3D Gaussians photometrically on a scene (3DGS, the original's defaults): L1 + D-SSIM,\n"
            "densification, SH degree schedule; every --test-every-th view (sorted by name) is held out\n"
            "for PSNR/SSIM. Writes OUT/point_cloud.ply (standard 3DGS PLY), OUT/summary.json and\n"
            "OUT/checkpoints/checkpoint.safetensors (every --checkpoint-every iterations, on Ctrl-C /\n"
            "SIGTERM and at the end); --resume continues from it exactly.");
  std::string scene_dir;
  int resolution = 1;
  RgbTrainOptions o;
  o.densify_until = -1;  // auto
  args.bind("scene", scene_dir, "scene directory (COLMAP, OPF or Pix4D, images/)").required()
      .bind("resolution", resolution, "3DGS-style downscaling factor: 1, 2, 4 or 8").short_name("r");
  rgb_train_options().declare(args, o);
  if (!args.parse(argc, argv)) return 0;
  rgb_train_options().apply(args, o);
  if (o.densify_until < 0) o.densify_until = auto_densify_until(o.iterations);
  if (o.random_background && o.white_background)
    throw UsageError("train-rgb: --random-background and --white-background exclude each other");

  SceneOptions scene_options;
  scene_options.resolution_factor = resolution;
  const Scene scene = load_scene(scene_dir, scene_options);
  const RgbTrainReport r = train_rgb(scene, o);
  if (r.interrupted) {
    std::fprintf(stderr,
                 "train-rgb: interrupted at iteration %d; continue with the same command and --resume:\n"
                 "  citylangsplat train-rgb --scene %s --out %s ... --resume\n",
                 r.iterations, scene_dir.c_str(), o.out_dir.c_str());
    return kInterruptedExit;
  }
  std::printf("iterations %d, %lld Gaussians, test PSNR %.2f dB, SSIM %.4f (%d test views), %.1f s\n", r.iterations,
              static_cast<long long>(r.gaussians), r.test_psnr, r.test_ssim, r.test_views, r.seconds);
  return 0;
}

}  // namespace cls
