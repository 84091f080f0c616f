#pragma once
// One stage of the pipeline: its inputs (the settings it runs under, serialised once, and the
// fingerprints of what it reads), the outputs that must exist, and the work. run_stage skips the work
// when the stage's stamp holds the fingerprint of the same inputs and the outputs exist, so a second
// `run` reuses what is current and redoes exactly what depends on a changed input; when it redoes a
// stage it says which inputs changed.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace cls {

enum class StageStatus {
  Done,         // ran and finished (its stamp is written)
  Reused,       // its stamp was current: nothing ran
  Interrupted,  // SIGINT/SIGTERM: stopped after a checkpoint; the run ends and resumes later
  Imported,     // its output was given (--rgb-model)
  Shared,       // its output is shared with other runs (--autoencoder of tiles)
  Skipped,      // it does not apply (reason: why)
  Stopped,      // it cannot run (reason: why); the run ends here
};

struct StageReport {
  StageStatus status = StageStatus::Done;
  std::string reason;                                // Skipped and Stopped: why
  double seconds = 0;                                // wall time of this invocation
  nlohmann::json fields = nlohmann::json::object();  // the stage's results (paths, scores, counts)

  static StageReport done(nlohmann::json fields = nlohmann::json::object());
  static StageReport interrupted();
  static StageReport with(StageStatus status, std::string reason, nlohmann::json fields = nlohmann::json::object());
  // {"status": "done" | "reused" | ... | "skipped: <reason>" | "stopped: <reason>", "seconds", <fields>}
  nlohmann::json to_json() const;
};

const char* status_name(StageStatus status);

struct Stage {
  std::string name;                              // as in run.json and the log: "labels", "train-language/langsplat"
  std::filesystem::path stamp;                   // the stamp of the finished stage; empty: never reused
  std::vector<std::filesystem::path> outputs;    // all must exist for the stage to be reused
  nlohmann::json inputs = nlohmann::json::object();  // settings and upstream fingerprints (fingerprint())
  nlohmann::json reused_fields = nlohmann::json::object();  // the report's fields when reused
  std::function<StageReport()> run;              // the work; status Done writes the stamp

  std::string fingerprint() const;  // of `inputs` (core/hash.h)
};

StageReport run_stage(const Stage& stage);

// The name of a step's stage for one method ("train-language/langsplat"; run_record.h stores it as
// run.json["train-language"]["langsplat"]).
inline std::string per_method(const std::string& step, const std::string& method) { return step + "/" + method; }

// Whether `stamp` records `fingerprint` (a missing or unreadable stamp is "no").
bool stage_is_current(const std::filesystem::path& stamp, const std::string& fingerprint);
// Writes the fingerprint and the inputs it was made of (so that a later run can say what changed).
void write_stamp(const std::filesystem::path& stamp, const std::string& fingerprint,
                 const nlohmann::json& inputs = nlohmann::json::object());

// A training stage resumes its checkpoint only when the checkpoint belongs to a run of the same
// inputs: `started` records the fingerprint when training starts; a checkpoint of other inputs is
// deleted so that it can never be resumed later. Returns whether to resume.
bool resume_training(const std::filesystem::path& started, const std::filesystem::path& checkpoint,
                     const std::string& fingerprint);

}  // namespace cls
