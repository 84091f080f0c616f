// The shared autoencoder (paper 3.2), trained on the SAM features only; or the one shared by all tiles
// (docs/scale.md). The published LangSplat baseline trains its own, with LangSplat's sizes and settings.
#include <algorithm>

#include "core/log.h"
#include "language/autoencoder_stage.h"
#include "pipeline/fingerprints.h"
#include "pipeline/stages.h"

namespace cls {
namespace {

Stage autoencoder_stage(RunContext& run, const std::string& name, const std::filesystem::path& file,
                        const AutoencoderConfig& config, const AutoencoderTrainOptions& train) {
  AutoencoderStageOptions o;
  o.features_dirs = {run.layout.features()};
  o.out = file;
  o.config = config;
  o.train = train;
  o.train.epochs = run.source.schedule.autoencoder_epochs;
  Stage s;
  s.name = name;
  s.stamp = RunLayout::stamp_beside(file);
  s.outputs = {file};
  s.inputs = {{"upstream", {{"features", run.fingerprint("features")}}},
              {"settings", autoencoder_options().settings_json(o)}};
  s.reused_fields = {{"file", file.string()}};
  s.run = [o, name] {
    const AutoencoderReport r = run_autoencoder_stage(o);
    log_info(cat("run: ", name, ": ", r.train_samples, " SAM features, held-out cosine ", r.holdout_cosine));
    return StageReport::done({{"file", o.out.string()}, {"holdout_cosine", r.holdout_cosine}});
  };
  return s;
}

}  // namespace

std::vector<Stage> autoencoder_stages(RunContext& run) {
  run.fingerprints["features"] = features_fingerprint(run.layout.features());
  std::vector<Stage> stages;
  if (run.config.field == "sparse") return stages;  // no field decodes latents: no autoencoder
  if (!run.config.autoencoder.empty()) {
    Stage shared;
    shared.name = "autoencoder";
    shared.run = [file = run.config.autoencoder] {
      return StageReport::with(StageStatus::Shared, "", {{"file", file}});
    };
    stages.push_back(shared);
  } else {
    stages.push_back(autoencoder_stage(run, "autoencoder", run.layout.autoencoder(), AutoencoderConfig{},
                                       AutoencoderTrainOptions{}));
  }
  const auto& b = run.config.baselines;
  if (std::find(b.begin(), b.end(), "langsplat-original") != b.end())
    stages.push_back(autoencoder_stage(run, "autoencoder-langsplat", run.layout.langsplat_autoencoder(),
                                       langsplat_autoencoder_config(), langsplat_autoencoder_training()));
  return stages;
}

}  // namespace cls
