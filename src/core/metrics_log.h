#pragma once
// Training curves: `metrics.jsonl`, one JSON object per line, appended and flushed as training goes
// (the report draws them; fields in docs/report.md). A resumed training first drops the rows after its
// checkpoint, so that the file is that of one uninterrupted run.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

namespace cls {

// Rows are written every metrics_interval(iterations) iterations (and at the last one): ~300 rows for
// 30,000 iterations, every iteration below 600.
int64_t metrics_interval(int64_t iterations);

// The rows of a metrics file; a line that is not a JSON object (a line cut short by a kill) is skipped.
// A missing file has no rows.
std::vector<nlohmann::json> read_metrics(const std::filesystem::path& path);

class MetricsLog {
 public:
  // A fresh training: `path` starts empty.
  static MetricsLog start(const std::filesystem::path& path);
  // A resumed training: only the rows `keep` accepts (those up to the checkpoint) stay; the file is
  // rewritten atomically before anything is appended.
  static MetricsLog resume(const std::filesystem::path& path, const std::function<bool(const nlohmann::json&)>& keep);

  // One row, flushed at once: a killed training loses no written row.
  void append(const nlohmann::json& row);
  // The last row written or kept (null when none): a resumed training continues its clock from it.
  const nlohmann::json& last() const { return last_; }

 private:
  MetricsLog(const std::filesystem::path& path, nlohmann::json last);
  std::filesystem::path path_;
  std::ofstream out_;
  nlohmann::json last_;
};

}  // namespace cls
