// citylangsplat render MODEL --scene DIR --out DIR: pictures and videos of a trained model.
#include <cstdio>
#include <string>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/log.h"
#include "render/render_job.h"

namespace cls {

int cmd_render(int argc, char** argv) {
  const RenderOptions d;
  Args args("render",
            "Render a trained model per view: RGB beside the photo with PSNR/SSIM, expected depth, a PCA picture\n"
            "of each language level, relevance maps of text queries, label maps beside the projected ground\n"
            "truth; with --path a camera path as PNG frames and MP4. Writes OUT/views/<view>/*.png and\n"
            "OUT/render.json. See docs/render.md.");
  args.positional("MODEL", "3DGS PLY, train-rgb output, 3DGS model dir (point_cloud/iteration_N) or language model dir")
      .option("scene", "", "scene directory (empty: the one the model records)")
      .option("out", "", "output directory")
      .option("views", d.views, "test (every --test-every-th by name, as train-rgb), all, or comma-separated image names")
      .option("what", "", "comma-separated: rgb, depth, features, relevance:TEXT (repeatable), labels "
                          "(empty: rgb,depth + features for a language model + labels where label maps or GT exist)")
      .option("labels", "", "label maps to draw (the raycast output: <view>/level1.png ... + legend.json)")
      .option("gt-points", "", "labelled point cloud for the ground-truth labels (empty: SCENE/gt/points.ply if present)")
      .option("taxonomy", "", "taxonomy JSON (empty: the label maps' legend, else the model's, else the built-in one)")
      .option("path", "", "also render a camera path: orbit or interpolate (through the scene's poses by name)")
      .option("frames", std::to_string(d.frames), "frames of the camera path")
      .option("fps", "30", "frame rate of the path's MP4")
      .option("test-every", std::to_string(d.test_every), "the test split: every this-th view by name (as train-rgb)")
      .option("resolution", std::to_string(d.resolution), "3DGS-style downscaling factor: 1, 2, 4 or 8 (as train-rgb)", "r")
      .flag("white-background", "white instead of black background");
  if (!args.parse(argc, argv)) return 0;
  if (!args.has("out")) throw UsageError("render: --out is required");

  RenderOptions o;
  o.model = args.get("MODEL");
  o.scene_dir = args.get("scene");
  o.out_dir = args.get("out");
  o.views = args.get("views");
  o.what = split_what(args.get("what"));
  o.labels_dir = args.get("labels");
  o.gt_points = args.get("gt-points");
  o.taxonomy_path = args.get("taxonomy");
  o.path = args.get("path");
  o.frames = args.get_int("frames");
  o.fps = args.get_double("fps");
  o.test_every = args.get_int("test-every");
  o.resolution = args.get_int("resolution");
  o.white_background = args.flag_set("white-background");
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
