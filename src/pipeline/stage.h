#pragma once
// One stage of the pipeline: a fingerprint of every input, the outputs that must exist, and the work.
// run_stage skips the work when the stage's stamp holds the same fingerprint and the outputs exist,
// so a second `run` reuses what is current and redoes exactly what depends on a changed input.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace cls {

struct StageReport {
  // "done", "reused", "interrupted", "skipped: <why>" or "stopped: <why>".
  std::string status;
  double seconds = 0;                                // wall time of this invocation
  nlohmann::json fields = nlohmann::json::object();  // the stage's results (paths, scores, counts)

  bool interrupted() const { return status == "interrupted"; }
  nlohmann::json to_json() const;  // {"status", "seconds", <fields>}
};

struct Stage {
  std::string name;                              // as in run.json and the log, e.g. "train-rgb"
  std::filesystem::path stamp;                   // JSON file holding the fingerprint of the finished stage
  std::vector<std::filesystem::path> outputs;    // all must exist for the stage to be reused
  std::string fingerprint;                       // of every input (core/hash.h)
  nlohmann::json reused_fields = nlohmann::json::object();  // the report's fields when reused
  std::function<StageReport()> run;              // the work; status "done" writes the stamp
};

StageReport run_stage(const Stage& stage);

// Whether `stamp` records `fingerprint` (a missing or unreadable stamp is "no").
bool stage_is_current(const std::filesystem::path& stamp, const std::string& fingerprint);
void write_stamp(const std::filesystem::path& stamp, const std::string& fingerprint);

// A training stage resumes its checkpoint only when the checkpoint belongs to a run of the same
// inputs: `started` records the fingerprint when training starts; a checkpoint of other inputs is
// deleted so that it can never be resumed later. Returns whether to resume.
bool resume_training(const std::filesystem::path& started, const std::filesystem::path& checkpoint,
                     const std::string& fingerprint);

}  // namespace cls
