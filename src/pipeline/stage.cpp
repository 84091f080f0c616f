#include "pipeline/stage.h"

#include <chrono>

#include "core/atomic_file.h"
#include "core/log.h"

namespace cls {
namespace fs = std::filesystem;

nlohmann::json StageReport::to_json() const {
  nlohmann::json j = {{"status", status}, {"seconds", seconds}};
  for (const auto& [key, value] : fields.items()) j[key] = value;
  return j;
}

bool stage_is_current(const fs::path& stamp, const std::string& fingerprint) {
  if (!fs::exists(stamp)) return false;
  try {
    return nlohmann::json::parse(read_text_file(stamp)).value("fingerprint", "") == fingerprint;
  } catch (const std::exception&) {
    return false;  // an unreadable stamp only means the stage runs again
  }
}

void write_stamp(const fs::path& stamp, const std::string& fingerprint) {
  write_text_atomic(stamp, nlohmann::json({{"fingerprint", fingerprint}}).dump(2) + "\n");
}

bool resume_training(const fs::path& started, const fs::path& checkpoint, const std::string& fingerprint) {
  const bool same = stage_is_current(started, fingerprint) && fs::exists(checkpoint);
  if (!same) fs::remove_all(checkpoint);
  write_stamp(started, fingerprint);
  return same;
}

StageReport run_stage(const Stage& stage) {
  const auto start = std::chrono::steady_clock::now();
  bool current = stage_is_current(stage.stamp, stage.fingerprint);
  for (const fs::path& p : stage.outputs) current = current && fs::exists(p);
  StageReport report;
  if (current) {
    report.status = "reused";
    report.fields = stage.reused_fields;
    log_info("run: " + stage.name + ": up to date (reused)");
  } else {
    report = stage.run();
    if (report.status == "done") write_stamp(stage.stamp, stage.fingerprint);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace cls
