#pragma once
// The whole method on one scene, stage by stage, reusing finished stages (docs/pipeline.md):
// inputs -> alignment check -> label maps (paper 3.1) -> features (3.1-3.2) -> shared autoencoder (3.2)
// -> photometric 3DGS -> language fields of CityLangSplat and the LangSplat baseline (3.3) -> queries
// for the taxonomy's classes -> evaluation against ground truth when the scene has it (section 4).
// Every stage has a fingerprint of its inputs (stage.h) and is skipped when its stamp matches; the
// training stages resume from their checkpoints after an interruption.
#include <filesystem>
#include <string>

#include "pipeline/pipeline_config.h"

namespace cls {

enum class PipelineOutcome {
  Finished,        // every stage ran or was reused
  Interrupted,     // SIGINT/SIGTERM: stopped after a checkpoint; the same run resumes
  MissingWeights,  // --models real without CLIP/SAM weights: stopped before the features
};

struct PipelineResult {
  PipelineOutcome outcome = PipelineOutcome::Finished;
  std::filesystem::path run_json;  // OUT/run.json
  std::filesystem::path report;    // OUT/report/index.html (docs/report.md), written by every run
  std::string message;             // MissingWeights: what is missing and how to get it
};

// Reads and validates every input before it writes anything (cls::Error naming the file).
PipelineResult run_pipeline(const PipelineConfig& config);

int exit_code(PipelineOutcome outcome);  // core/exit_codes.h

}  // namespace cls
