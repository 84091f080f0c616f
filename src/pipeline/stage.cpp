#include "pipeline/stage.h"

#include <chrono>

#include "core/atomic_file.h"
#include "core/hash.h"
#include "core/log.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

nlohmann::json read_stamp(const fs::path& stamp) {
  if (!fs::exists(stamp)) return nullptr;
  try {
    return nlohmann::json::parse(read_text_file(stamp));
  } catch (const std::exception&) {
    return nullptr;  // an unreadable stamp only means the stage runs again
  }
}

// The top-level inputs that differ between two runs of a stage ("alpha", "upstream"), for the log.
std::string changed_inputs(const nlohmann::json& before, const nlohmann::json& now) {
  std::string keys;
  for (const auto& [key, value] : now.items())
    if (!before.contains(key) || before[key] != value) keys += (keys.empty() ? "" : ", ") + key;
  for (const auto& [key, value] : before.items())
    if (!now.contains(key)) keys += (keys.empty() ? "" : ", ") + key;
  return keys;
}

}  // namespace

const char* status_name(StageStatus status) {
  switch (status) {
    case StageStatus::Done: return "done";
    case StageStatus::Reused: return "reused";
    case StageStatus::Interrupted: return "interrupted";
    case StageStatus::Imported: return "imported";
    case StageStatus::Shared: return "shared";
    case StageStatus::Skipped: return "skipped";
    case StageStatus::Stopped: return "stopped";
  }
  return "?";
}

StageReport StageReport::done(nlohmann::json fields) { return with(StageStatus::Done, "", std::move(fields)); }
StageReport StageReport::interrupted() { return with(StageStatus::Interrupted, ""); }
StageReport StageReport::with(StageStatus status, std::string reason, nlohmann::json fields) {
  StageReport r;
  r.status = status;
  r.reason = std::move(reason);
  r.fields = std::move(fields);
  return r;
}

nlohmann::json StageReport::to_json() const {
  const std::string name = status_name(status);
  nlohmann::json j = {{"status", reason.empty() ? name : name + ": " + reason}, {"seconds", seconds}};
  for (const auto& [key, value] : fields.items()) j[key] = value;
  return j;
}

std::string Stage::fingerprint() const { return hex64(fnv1a64(inputs.dump())); }

bool stage_is_current(const fs::path& stamp, const std::string& fingerprint) {
  const nlohmann::json j = read_stamp(stamp);
  return j.is_object() && j.value("fingerprint", "") == fingerprint;
}

void write_stamp(const fs::path& stamp, const std::string& fingerprint, const nlohmann::json& inputs) {
  write_text_atomic(stamp, nlohmann::json({{"fingerprint", fingerprint}, {"inputs", inputs}}).dump(2) + "\n");
}

bool resume_training(const fs::path& started, const fs::path& checkpoint, const std::string& fingerprint) {
  const bool same = stage_is_current(started, fingerprint) && fs::exists(checkpoint);
  if (!same) fs::remove_all(checkpoint);
  write_stamp(started, fingerprint);
  return same;
}

StageReport run_stage(const Stage& stage) {
  const auto start = std::chrono::steady_clock::now();
  const std::string fingerprint = stage.fingerprint();
  bool current = !stage.stamp.empty() && stage_is_current(stage.stamp, fingerprint);
  for (const fs::path& p : stage.outputs) current = current && fs::exists(p);
  StageReport report;
  if (current) {
    report = StageReport::with(StageStatus::Reused, "", stage.reused_fields);
    log_info("run: " + stage.name + ": up to date (reused)");
  } else {
    if (!stage.stamp.empty()) {
      const nlohmann::json before = read_stamp(stage.stamp);
      if (before.is_object() && before.contains("inputs") && before["inputs"] != stage.inputs)
        log_info("run: " + stage.name + ": inputs changed (" + changed_inputs(before["inputs"], stage.inputs) +
                 "): running it again");
    }
    report = stage.run();
    if (report.status == StageStatus::Done && !stage.stamp.empty()) write_stamp(stage.stamp, fingerprint, stage.inputs);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace cls
