// The features (paper 3.1-3.2): SAM segments and CityGML regions of every view through the run's
// feature provider (features/feature_stage.h). Real weights may be absent: the run stops here and says
// how to get them.
#include "core/interrupt.h"
#include "core/log.h"
#include "features/feature_stage.h"
#include "pipeline/fingerprints.h"
#include "pipeline/stages.h"

namespace cls {

std::vector<Stage> feature_stages(RunContext& run) {
  Stage s;
  s.name = "features";
  if (!run.source.provider) {
    s.run = [&run] {
      run.outcome = PipelineOutcome::MissingWeights;
      run.message = run.source.missing_weights;
      return StageReport::with(StageStatus::Stopped, "no model weights", {{"reason", run.source.missing_weights}});
    };
    return {s};
  }
  run.fingerprints["images"] = images_fingerprint(run.scene);
  FeatureStageOptions o;
  o.labels_dir = run.layout.labels();
  o.out_dir = run.layout.features();
  o.alpha = run.config.alpha;
  o.region_mode = run.config.regions == "instance" ? RegionMode::Instance : RegionMode::Class;
  s.stamp = RunLayout::stamp_in(o.out_dir);
  s.outputs = {o.out_dir / "features.json"};
  // The stage's own per-view stamps (features/feature_stage.h) remain its resume within the stage.
  s.inputs = {{"upstream", {{"labels", run.fingerprint("labels")}, {"images", run.fingerprint("images")}}},
              {"provider", run.source.provider->spec()},
              {"settings", feature_stage_options().settings_json(o)}};
  s.reused_fields = {{"dir", o.out_dir.string()}, {"computed_views", 0}};
  s.run = [&run, o] {
    const int computed = run_feature_stage(run.language_scene, *run.source.provider, run.city.taxonomy, o);
    if (interrupt_requested()) return StageReport::interrupted();
    log_info(cat("run: features: ", computed, " views computed, ", run.language_scene.views.size() - computed, " reused (",
                 o.out_dir.string(), ")"));
    return StageReport::done({{"dir", o.out_dir.string()}, {"computed_views", computed}});
  };
  return {s};
}

}  // namespace cls
