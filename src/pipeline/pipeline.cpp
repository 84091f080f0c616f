#include "pipeline/pipeline.h"

#include "core/exit_codes.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "pipeline/stages.h"
#include "report/report.h"

namespace cls {

const std::vector<PipelineStep>& pipeline_steps() {
  static const std::vector<PipelineStep> steps = {
      {"georef", georef_stages},     {"align", align_stages},          {"labels", label_stages},         {"features", feature_stages},
      {"autoencoder", autoencoder_stages}, {"train-rgb", train_rgb_stages}, {"render", render_stages},
      {"train-language", language_stages}, {"query", query_stages},     {"evaluate", evaluate_stages}};
  return steps;
}

std::vector<std::string> pipeline_step_names() {
  std::vector<std::string> names;
  for (const PipelineStep& s : pipeline_steps()) names.push_back(s.name);
  return names;
}

int exit_code(PipelineOutcome outcome) {
  switch (outcome) {
    case PipelineOutcome::Finished: return kExitOk;
    case PipelineOutcome::Interrupted: return kInterruptedExit;
    case PipelineOutcome::MissingWeights: return kExitMissingWeights;
  }
  return kExitInternal;
}

namespace {

// Every run ends with its report, also one that stopped early: it shows what was done.
PipelineResult finish(RunContext& run) {
  run.record.set("report", run.layout.report_page().string());
  run.record.save();
  PipelineResult result{run.outcome, run.record.file(), write_report(run.layout.root()), run.message};
  log_info("run: report: " + result.report.string());
  return result;
}

// Stages that do not poll the signal flag themselves finish their work; the run stops after them.
bool stopped_by_signal(RunContext& run, const std::string& after) {
  if (!interrupt_requested()) return false;
  run.record.set("interrupted_after", after);
  log_warn("run: interrupted after " + after + "; run the same command again to continue");
  run.outcome = PipelineOutcome::Interrupted;
  return true;
}

}  // namespace

PipelineResult run_pipeline(const PipelineConfig& config, const StageObserver& before_stage) {
  RunContext run = open_run(config);
  install_interrupt_handlers();
  for (const PipelineStep& step : pipeline_steps()) {
    const std::vector<Stage> stages = step.stages(run);
    for (const Stage& stage : stages) {
      // A step's later stages (the second autoencoder, the next method) wait for a signal as steps do.
      if (&stage != &stages.front() && stopped_by_signal(run, (&stage - 1)->name)) return finish(run);
      if (before_stage) before_stage(stage.name);
      const StageReport report = run_stage(stage);
      run.record.add(stage.name, report);
      if (report.status == StageStatus::Interrupted) {
        log_warn("run: interrupted during " + stage.name + "; run the same command again to resume");
        run.outcome = PipelineOutcome::Interrupted;
        return finish(run);
      }
      if (report.status == StageStatus::Stopped) return finish(run);
    }
    if (stopped_by_signal(run, step.name)) return finish(run);
    if (step.name == run.config.stop_after) {
      log_info("run: stopped after " + step.name + " (--stop-after " + step.name + ")");
      return finish(run);
    }
  }
  log_info("run: done. Results: " + run.record.file().string());
  return finish(run);
}

}  // namespace cls
