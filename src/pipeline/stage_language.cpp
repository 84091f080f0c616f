// The language fields (paper 3.3), one per method on identical inputs: CityLangSplat under the
// coverage-aware loss, LangSplat's objective on the shared autoencoder, and LangSplat as published (its
// own autoencoder, normalised splatting).
#include "core/log.h"
#include "pipeline/fingerprints.h"
#include "pipeline/stages.h"
#include "language/language_training.h"
#include "splat/train_rgb.h"

namespace cls {
namespace {

Stage language_stage(RunContext& run, const std::string& method) {
  const bool original = method == "langsplat-original";
  LanguageTrainOptions o;
  o.geometry_ply = run.geometry().string();
  o.features_dir = run.layout.features().string();
  o.autoencoder_path = (original ? run.layout.langsplat_autoencoder()
                        : run.config.autoencoder.empty() ? run.layout.autoencoder()
                                                         : std::filesystem::path(run.config.autoencoder))
                           .string();
  o.out_dir = run.layout.language(method).string();
  o.iterations = run.source.schedule.language_iterations;
  o.lambda_sam = run.config.lambda_sam;
  o.lambda_citygml = run.config.lambda_citygml;
  o.baseline = method != "citylangsplat";
  o.normalize_latents = original;  // LangSplat's renderer splats each Gaussian's normalised feature
  o.field = run.config.field;
  o.codebook_size = run.config.codebook_size;
  o.top_k = run.config.top_k;
  const bool sparse = o.field == "sparse";
  if (sparse) o.autoencoder_path.clear();  // the sparse field has none
  o.test_every = RgbTrainOptions{}.test_every;  // train-rgb's held-out views stay unseen: evaluate scores 2D on them
  nlohmann::json settings = language_train_options().settings_json(o);
  // The baseline's objective has no lambdas (LangSplat's L1 on every pixel): changing them keeps it.
  if (o.baseline) settings.erase("lambda_sam"), settings.erase("lambda_citygml");
  // A dense field's settings as before the sparse field existed (its stages stay reused): the sparse field's
  // own options only with it.
  if (!sparse)
    for (const char* key : {"field", "codebook_size", "top_k", "logit_lr", "codebook_lr", "sparse_warmup", "lift_temperature",
                            "sparse_distance"})
      settings.erase(key);
  Stage s;
  s.name = per_method("train-language", method);
  s.stamp = RunLayout::stamp_in(o.out_dir);
  s.outputs = {LanguageModelFiles{o.out_dir}.model_json(), LanguageModelFiles{o.out_dir}.city_objects()};
  nlohmann::json upstream = {{"geometry", run.fingerprint("geometry")}, {"features", run.fingerprint("features")}};
  if (!sparse) upstream["autoencoder"] = file_fingerprint(o.autoencoder_path);
  s.inputs = {{"upstream", upstream},
              {"objective", o.baseline ? "langsplat" : "citylangsplat"},
              {"settings", settings}};
  s.reused_fields = {{"dir", o.out_dir}};
  s.run = [&run, o, method, fingerprint = s.fingerprint()] {
    LanguageTrainOptions t = o;
    t.resume = resume_training(RunLayout::training_started(t.out_dir), RunLayout::checkpoints(t.out_dir), fingerprint);
    const LanguageTrainReport r = train_language(run.language_scene, t);
    if (r.interrupted) return StageReport::interrupted();
    log_info(cat("run: train-language (", method, "): ", t.iterations, " iterations per level in ", r.seconds, " s"));
    return StageReport::done({{"dir", t.out_dir}, {"resumed", t.resume}});
  };
  return s;
}

}  // namespace

std::vector<Stage> language_stages(RunContext& run) {
  std::vector<Stage> stages;
  for (const std::string& method : run.methods()) stages.push_back(language_stage(run, method));
  return stages;
}

}  // namespace cls
