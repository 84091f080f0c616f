// The label maps (paper 3.1): the city model raycast into every view (raycast/label_export.h).
#include "core/log.h"
#include "pipeline/fingerprints.h"
#include "pipeline/stages.h"
#include "raycast/label_export.h"

namespace cls {

std::vector<Stage> label_stages(RunContext& run) {
  const PipelineConfig& c = run.config;
  Stage s;
  s.name = "labels";
  const auto dir = run.layout.labels();
  s.stamp = RunLayout::stamp_in(dir);
  s.outputs = {dir / "objects.json", dir / kLabelsCityTransform, dir / "legend.json"};
  s.inputs = {{"city_model", file_fingerprint(c.city)},
              {"city_transform", file_fingerprint(run.city_transform)},
              {"taxonomy", taxonomy_fingerprint(run.city.taxonomy)},
              {"lod", c.city_options.lod},
              {"views", views_fingerprint(run.language_scene)}};
  s.reused_fields = {{"dir", dir.string()}};
  s.run = [&run, dir] {
    const LabelExportSummary e = export_label_maps(run.language_scene, run.city, dir);
    log_info(cat("run: labels: wrote ", e.views, " views to ", dir.string(), " (mean coverage ", 100 * e.mean_coverage,
                 "%)"));
    return StageReport::done({{"dir", dir.string()}, {"mean_coverage", e.mean_coverage}});
  };
  run.fingerprints["labels"] = s.fingerprint();
  return {s};
}

}  // namespace cls
