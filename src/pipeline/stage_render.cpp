// Pictures of the photometric model: the held-out views beside their photos (PSNR, SSIM) and depth
// (render/render_job.h), on the scene the run holds.
#include "core/log.h"
#include "pipeline/fingerprints.h"
#include "pipeline/stages.h"
#include "render/render_job.h"

namespace cls {

std::vector<Stage> render_stages(RunContext& run) {
  run.fingerprints["geometry"] = file_fingerprint(run.geometry());
  RenderOptions o;
  // The PLY itself: the folder's highest point_cloud/iteration_N may be left from an earlier schedule.
  o.model = run.geometry().string();
  o.out_dir = run.layout.render().string();
  o.what = {"rgb", "depth"};
  o.resolution = run.config.resolution;
  Stage s;
  s.name = "render";
  s.stamp = RunLayout::stamp_in(run.layout.render());
  s.outputs = {run.layout.render() / "render.json"};
  s.inputs = {{"upstream", {{"geometry", run.fingerprint("geometry")}, {"images", run.fingerprint("images")}}},
              {"settings", {{"what", o.what}, {"resolution", o.resolution}, {"views", o.views}}}};
  s.reused_fields = {{"dir", o.out_dir}};
  s.run = [&run, o] {
    const nlohmann::json r = render_views(load_render_model(o.model), run.scene, o);
    log_info(cat("run: render: ", r["views"].size(), " held-out views, mean PSNR ", r.value("mean_psnr", 0.0), " dB (",
                 o.out_dir, ")"));
    return StageReport::done({{"dir", o.out_dir}, {"mean_psnr", r.value("mean_psnr", 0.0)},
                              {"mean_ssim", r.value("mean_ssim", 0.0)}});
  };
  return {s};
}

}  // namespace cls
