#pragma once
// OUT/run.json, what a run did (docs/pipeline.md): the settings, the feature source and its warning,
// "stages" in the order they ran, and per stage {"status", "seconds", ...}; a stage run once per
// method ("train-language/langsplat") is stored as run.json["train-language"]["langsplat"].
// Saved atomically after every stage, so an interrupted run leaves a valid record.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "pipeline/stage.h"

namespace cls {

class RunRecord {
 public:
  RunRecord(std::filesystem::path file, nlohmann::json header);

  void add(const std::string& stage, const StageReport& report);  // and save
  void set(const std::string& key, nlohmann::json value);         // a top-level field (not saved yet)
  void save() const;

  const nlohmann::json& json() const { return json_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  nlohmann::json json_;
};

}  // namespace cls
