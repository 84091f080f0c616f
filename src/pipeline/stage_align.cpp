// The align stage: refine the city transform from the sparse points (city_alignment.h), then check
// the transform the label maps use (a warning, not a failure, so a user sees it before training).
#include "core/log.h"
#include "pipeline/city_alignment.h"
#include "pipeline/stages.h"
#include "raycast/alignment.h"

namespace cls {

std::vector<Stage> align_stages(RunContext& run) {
  Stage s;
  s.name = "align";
  s.run = [&run] {
    const PipelineConfig& c = run.config;
    const CityAlignment alignment =
        align_city_model(run.scene, run.city, c.align, c.align_distance, run.layout.align_transform());
    if (alignment.applied) run.city_transform = alignment.transform.string();
    if (!run.scene.points.empty()) {
      const AlignmentStats a = check_alignment(run.scene, run.city, c.align_distance);
      log_info(cat("run: align-check: ", 100 * a.fraction_within, "% of sparse points within ", c.align_distance,
                   " m of the city model (median ", a.median, " m)"));
      if (a.fraction_within < kMisalignedFraction)
        log_warn("run: the city model and the scene look misaligned; check the city transform");
      run.record.set("align_check",
                     {{"fraction_within", a.fraction_within}, {"median", a.median}, {"threshold", c.align_distance}});
    }
    return StageReport::done(alignment.record);
  };
  return {s};
}

}  // namespace cls
