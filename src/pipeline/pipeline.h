#pragma once
// The whole method on one scene, stage by stage, reusing finished stages (docs/pipeline.md): the steps
// of pipeline_steps() in order over one RunContext (run_context.h):
// align -> labels (paper 3.1) -> features (3.1-3.2) -> autoencoder (3.2) -> train-rgb -> render ->
// train-language for CityLangSplat and the baselines (3.3) -> query for the taxonomy's classes ->
// evaluate against ground truth when the scene has it (section 4).
// Every stage has a fingerprint of its inputs (stage.h) and is skipped when its stamp matches; the
// training stages resume from their checkpoints after an interruption.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "pipeline/pipeline_config.h"
#include "pipeline/run_context.h"
#include "pipeline/stage.h"

namespace cls {

struct PipelineResult {
  PipelineOutcome outcome = PipelineOutcome::Finished;
  std::filesystem::path run_json;  // OUT/run.json
  std::filesystem::path report;    // OUT/report/index.html (docs/report.md), written by every run
  std::string message;             // MissingWeights: what is missing and how to get it
};

// One step of the run: the stages it makes from what the run holds so far (one per method for the
// per-method steps), built when the step's turn comes, so that they see their upstream's results.
struct PipelineStep {
  std::string name;
  std::function<std::vector<Stage>(RunContext&)> stages;
};
const std::vector<PipelineStep>& pipeline_steps();
std::vector<std::string> pipeline_step_names();

// Called with each stage's name before it runs (tests interrupt a run here).
using StageObserver = std::function<void(const std::string& stage)>;

// Reads and validates every input before it writes anything (cls::Error naming the file).
PipelineResult run_pipeline(const PipelineConfig& config, const StageObserver& before_stage = {});

int exit_code(PipelineOutcome outcome);  // core/exit_codes.h

}  // namespace cls
