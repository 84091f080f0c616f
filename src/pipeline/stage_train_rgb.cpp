// The photometric model (3DGS, splat/train_rgb.h), or an imported 3DGS PLY (--rgb-model).
#include "core/log.h"
#include "pipeline/stages.h"
#include "splat/train_rgb.h"

namespace cls {

std::vector<Stage> train_rgb_stages(RunContext& run) {
  Stage s;
  s.name = "train-rgb";
  if (!run.config.rgb_model.empty()) {
    s.run = [ply = run.config.rgb_model] { return StageReport::with(StageStatus::Imported, "", {{"ply", ply}}); };
    return {s};
  }
  RgbTrainOptions o;
  o.out_dir = run.layout.rgb().string();
  o.iterations = run.source.schedule.rgb_iterations;
  o.densify_until = auto_densify_until(o.iterations);
  const std::filesystem::path ply = run.layout.rgb_ply();
  s.stamp = RunLayout::stamp_in(run.layout.rgb());
  s.outputs = {ply};
  s.inputs = {{"upstream", {{"images", run.fingerprint("images")}}}, {"settings", rgb_train_options().settings_json(o)}};
  s.reused_fields = {{"ply", ply.string()}};
  s.run = [&run, o, ply, fingerprint = s.fingerprint()] {
    RgbTrainOptions t = o;
    const std::filesystem::path dir = t.out_dir;
    t.resume = resume_training(RunLayout::training_started(dir), rgb_checkpoint(dir), fingerprint);
    const RgbTrainReport r = train_rgb(run.scene, t);
    if (r.interrupted) return StageReport::interrupted();
    log_info(cat("run: train-rgb: ", r.iterations, " iterations, ", r.gaussians, " Gaussians, test PSNR ", r.test_psnr,
                 " dB over ", r.test_views, " views"));
    return StageReport::done({{"ply", ply.string()}, {"test_psnr", r.test_psnr}, {"test_ssim", r.test_ssim},
                              {"gaussians", r.gaussians}, {"iterations", r.iterations}, {"resumed", t.resume}});
  };
  return {s};
}

}  // namespace cls
