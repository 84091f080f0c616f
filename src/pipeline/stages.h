#pragma once
// The stages of `run`, one function each over the run's context (run_context.h), in the order of
// pipeline_steps() (pipeline.cpp). Each returns the stages it makes now: their inputs (settings
// serialised once by the stage's options, plus the fingerprints of upstream results), outputs and work;
// a per-method step returns one stage per method, a step that does not apply returns a stage that says
// why. docs/development.md says how to add one.
#include <vector>

#include "pipeline/run_context.h"
#include "pipeline/stage.h"

namespace cls {

std::vector<Stage> georef_stages(RunContext& run);       // the city transform from the photos' GPS (run --georef)
std::vector<Stage> align_stages(RunContext& run);        // refine the city transform (run --align)
std::vector<Stage> label_stages(RunContext& run);        // label maps and coverage (paper 3.1)
std::vector<Stage> feature_stages(RunContext& run);      // SAM and CityGML features (3.1-3.2)
std::vector<Stage> autoencoder_stages(RunContext& run);  // the shared autoencoder (3.2); LangSplat's own
std::vector<Stage> train_rgb_stages(RunContext& run);    // the photometric 3DGS model
std::vector<Stage> render_stages(RunContext& run);       // held-out views beside their photos, depth
std::vector<Stage> language_stages(RunContext& run);     // a language field per method (3.3)
std::vector<Stage> query_stages(RunContext& run);        // the taxonomy's classes as text queries
std::vector<Stage> evaluate_stages(RunContext& run);     // the paper's tables against labelled points (4)

}  // namespace cls
