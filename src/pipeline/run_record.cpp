#include "pipeline/run_record.h"

#include <algorithm>

#include "core/atomic_file.h"

namespace cls {

RunRecord::RunRecord(std::filesystem::path file, nlohmann::json header) : file_(std::move(file)), json_(std::move(header)) {
  json_["stages"] = nlohmann::json::array();
}

void RunRecord::add(const std::string& stage, const StageReport& report) {
  const size_t slash = stage.find('/');
  if (slash == std::string::npos) json_[stage] = report.to_json();
  else json_[stage.substr(0, slash)][stage.substr(slash + 1)] = report.to_json();
  nlohmann::json& order = json_["stages"];
  if (std::find(order.begin(), order.end(), stage) == order.end()) order.push_back(stage);
  save();
}

void RunRecord::set(const std::string& key, nlohmann::json value) { json_[key] = std::move(value); }

void RunRecord::save() const { write_text_atomic(file_, json_.dump(2) + "\n"); }

}  // namespace cls
