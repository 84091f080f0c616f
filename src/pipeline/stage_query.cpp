// Queries for the taxonomy's classes on every method's language field (query/query_job.h): scores and
// selections per Gaussian, relevance maps of the first view; with the run's scene and feature provider.
#include <ATen/core/grad_mode.h>

#include "core/log.h"
#include "language/language_model.h"
#include "pipeline/fingerprints.h"
#include "pipeline/stages.h"
#include "query/query_job.h"

namespace cls {

std::vector<Stage> query_stages(RunContext& run) {
  std::vector<std::string> classes;
  for (const SemanticClass& k : run.city.taxonomy.classes) classes.push_back(k.name);
  std::vector<Stage> stages;
  for (const std::string& method : run.methods()) {
    const std::filesystem::path model_dir = run.layout.language(method);
    const LanguageModelFiles files{model_dir};  // the file that holds the trained field
    const std::string latents = file_fingerprint(run.config.field == "sparse" ? files.sparse() : files.latents());
    run.fingerprints[per_method("latents", method)] = latents;
    QueryOptions q;
    q.model_dir = model_dir.string();
    q.texts = classes;
    q.out_dir = run.layout.query(method).string();
    q.views = {run.language_scene.views.front().name};
    Stage s;
    s.name = per_method("query", method);
    s.stamp = RunLayout::stamp_in(q.out_dir);
    s.outputs = {run.layout.query(method) / "query.json"};
    s.inputs = {{"upstream", {{"latents", latents}}},
                {"settings", {{"texts", q.texts}, {"views", q.views}, {"level", q.level}, {"threshold", q.threshold}}}};
    s.reused_fields = {{"dir", q.out_dir}};
    s.run = [&run, q] {
      at::NoGradGuard no_grad;
      LanguageModel model = load_language_model(q.model_dir);
      run_query(model, *run.source.provider, {&run.language_scene.views.front()}, q);
      log_info(cat("run: query: scores and selections for ", q.texts.size(), " classes in ", q.out_dir));
      return StageReport::done({{"dir", q.out_dir}});
    };
    stages.push_back(s);
  }
  return stages;
}

}  // namespace cls
