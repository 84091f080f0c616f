#pragma once
// The run report: RUN_DIR/report/index.html, one static page (no server, no network, no script) of
// what a run directory holds: the stages with their times and settings, label-map previews, training
// curves, test renders next to the photos, the evaluation's Tables 1-3 with the prediction/GT images,
// and the relevance maps of both methods side by side. It only reads files; every input but run.json is
// optional, and what is missing is said in one line instead of a broken image. Images are referenced by
// paths relative to report/, so the page opens from disk and the run directory can be moved.
// What it reads: docs/report.md.
#include <filesystem>

namespace cls {

// Writes RUN_DIR/report/index.html atomically and returns its path. cls::Error naming run.json when
// it is missing or not a JSON object.
std::filesystem::path write_report(const std::filesystem::path& run_dir);

}  // namespace cls
