#include "core/metrics_log.h"

#include <algorithm>
#include <sstream>
#include <string>

#include "core/atomic_file.h"
#include "core/error.h"

namespace cls {
namespace fs = std::filesystem;

int64_t metrics_interval(int64_t iterations) { return std::max<int64_t>(1, iterations / 300); }

std::vector<nlohmann::json> read_metrics(const fs::path& path) {
  std::vector<nlohmann::json> rows;
  if (!fs::exists(path)) return rows;
  std::istringstream in(read_text_file(path));
  for (std::string line; std::getline(in, line);) {
    nlohmann::json row = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (row.is_object()) rows.push_back(std::move(row));
  }
  return rows;
}

MetricsLog::MetricsLog(const fs::path& path, nlohmann::json last) : path_(path), last_(std::move(last)) {
  out_.open(path, std::ios::binary | std::ios::app);
  if (!out_) fail(path.string(), "cannot open the metrics file for appending");
}

MetricsLog MetricsLog::start(const fs::path& path) {
  write_text_atomic(path, "");
  return MetricsLog(path, nullptr);
}

MetricsLog MetricsLog::resume(const fs::path& path, const std::function<bool(const nlohmann::json&)>& keep) {
  std::string kept;
  nlohmann::json last;
  for (const nlohmann::json& row : read_metrics(path)) {
    if (!keep(row)) continue;
    kept += row.dump() + "\n";
    last = row;
  }
  write_text_atomic(path, kept);
  return MetricsLog(path, std::move(last));
}

void MetricsLog::append(const nlohmann::json& row) {
  out_ << row.dump() << '\n';
  out_.flush();
  if (!out_) fail(path_.string(), "cannot append a row");
  last_ = row;
}

}  // namespace cls
