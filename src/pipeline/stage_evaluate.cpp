// The evaluation (paper section 4) when the scene has a labelled point cloud: every method's language
// field and the label maps themselves against it (eval/evaluation.h).
#include <cstdio>

#include "eval/evaluation.h"
#include "language/language_model.h"
#include "pipeline/fingerprints.h"
#include "pipeline/stages.h"
#include "splat/train_rgb.h"

namespace cls {
namespace fs = std::filesystem;

std::vector<Stage> evaluate_stages(RunContext& run) {
  Stage s;
  s.name = "evaluate";
  const fs::path gt = SceneFiles{run.config.scene_dir}.gt_points();
  if (!fs::exists(gt)) {
    s.run = [gt] { return StageReport::with(StageStatus::Skipped, "no " + gt.string()); };
    return {s};
  }
  const fs::path dir = run.layout.eval();
  nlohmann::json latents = nlohmann::json::object();
  for (const std::string& method : run.methods()) latents[method] = run.fingerprint(per_method("latents", method));
  s.stamp = RunLayout::stamp_in(dir);
  s.outputs = {dir / "eval.md", dir / "eval.json"};
  s.inputs = {{"upstream", {{"gt", file_fingerprint(gt)}, {"labels", run.fingerprint("labels")}, {"latents", latents}}},
              {"tables", kEvaluationTables}};
  const nlohmann::json files = {{"tables", (dir / "eval.md").string()}, {"json", (dir / "eval.json").string()}};
  s.reused_fields = files;
  s.run = [&run, gt, dir, files] {
    EvaluationOptions e;
    e.gt_points = gt.string();
    e.labels_dir = run.layout.labels().string();
    e.test_every = RgbTrainOptions{}.test_every;
    std::vector<std::pair<std::string, nlohmann::json>> results;
    for (const std::string& method : run.methods()) {
      e.out_dir = (dir / method).string();
      const LanguageModel model = load_language_model(run.layout.language(method).string());
      results.emplace_back(method, evaluate_model(run.language_scene, model, *run.source.provider, run.city.taxonomy, e));
    }
    e.out_dir = (dir / kLabelMapsMethod).string();
    results.emplace_back(kLabelMapsMethod, evaluate_label_maps(run.language_scene, run.city.taxonomy, e));
    const std::string md =
        write_evaluation(dir, results, run.config.scene_dir.string(), gt.string(), run.source.warning);
    std::fprintf(stdout, "%s", md.c_str());
    return StageReport::done(files);
  };
  return {s};
}

}  // namespace cls
