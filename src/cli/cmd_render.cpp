// citylangsplat render MODEL --scene DIR --out DIR: pictures and videos of a trained model.
#include <cstdio>
#include <string>
#include <vector>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/log.h"
#include "render/render_job.h"

namespace cls {
namespace {

// --what: a comma-separated list of outputs, split as split_what does (a relevance text may hold commas).
Codec<std::vector<std::string>> what_codec() {
  Codec<std::vector<std::string>> c = default_codec<std::vector<std::string>>();
  c.parse = [](const std::string& s) { return split_what(s); };
  return c;
}

}  // namespace

int cmd_render(int argc, char** argv) {
  Args args("render",
            "Render a trained model per view: RGB beside the photo with PSNR/SSIM, expected depth, a PCA picture\n"
            "of each language level, relevance maps of text queries, label maps beside the projected ground\n"
            "truth; with --path a camera path as PNG frames and MP4. Writes OUT/views/<view>/*.png and\n"
            "OUT/render.json. See docs/render.md.");
  RenderOptions o;
  args.positional("MODEL", o.model, "3DGS PLY, train-rgb output, 3DGS model dir (point_cloud/iteration_N) or language model dir")
      .bind("scene", o.scene_dir, "scene directory (empty: the one the model records)")
      .bind("out", o.out_dir, "output directory")
      .required()
      .bind("views", o.views, "test (every --test-every-th by name, as train-rgb), all, or comma-separated image names")
      .bind("what", o.what, "comma-separated: rgb, depth, features, relevance:TEXT (repeatable), labels "
                            "(empty: rgb,depth + features for a language model + labels where label maps or GT exist)",
            what_codec())
      .bind("labels", o.labels_dir, "label maps to draw (the raycast output: <view>/level1.png ... + legend.json)")
      .bind("gt-points", o.gt_points, "labelled point cloud for the ground-truth labels (empty: SCENE/gt/points.ply if present)")
      .bind("taxonomy", o.taxonomy_path, "taxonomy JSON (empty: the label maps' legend, else the model's, else the built-in one)")
      .bind("path", o.path, "also render a camera path: orbit or interpolate (through the scene's poses by name)")
      .bind("frames", o.frames, "frames of the camera path")
      .bind("fps", o.fps, "frame rate of the path's MP4")
      .bind("test-every", o.test_every, "the test split: every this-th view by name (as train-rgb)")
      .bind("resolution", o.resolution, "3DGS-style downscaling factor: 1, 2, 4 or 8 (as train-rgb)")
      .short_name("r")
      .flag("white-background", o.white_background, "white instead of black background");
  if (!args.parse(argc, argv)) return 0;
  const nlohmann::json r = render_views(o);
  char line[200];
  std::snprintf(line, sizeof line, "render: %zu views", r["views"].size());
  std::string msg = line;
  if (r.contains("mean_psnr")) {
    std::snprintf(line, sizeof line, ", mean PSNR %.2f dB, SSIM %.4f", r["mean_psnr"].get<double>(), r["mean_ssim"].get<double>());
    msg += line;
  }
  if (r.contains("path")) msg += ", " + r["path"]["files"]["rgb_mp4"].get<std::string>();
  log_info(msg + " -> " + o.out_dir + "/render.json");
  return 0;
}

}  // namespace cls
