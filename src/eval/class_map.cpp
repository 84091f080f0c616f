#include "eval/class_map.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"

namespace cls {

ClassMap read_class_map(const std::string& path, const Taxonomy& taxonomy) {
  ClassMap map;
  map.file = path;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(path));
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("class map: not JSON: ") + e.what());
  }
  if (!j.is_object() || !j.contains("classes") || !j["classes"].is_object() || j["classes"].empty())
    fail(path, "class map: needs \"classes\": {\"<label value>\": \"<taxonomy class>\" or null, ...}");
  map.name = j.value("name", std::string());
  for (const auto& [key, value] : j["classes"].items()) {
    size_t used = 0;
    int64_t label = 0;
    try {
      label = std::stoll(key, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != key.size()) fail(path, "class map: the key '" + key + "' is not an integer label value");
    if (value.is_null()) {
      map.classes[label] = -1;
      continue;
    }
    if (!value.is_string()) fail(path, "class map: label " + key + " maps to " + value.dump() + ", not a class name or null");
    const int id = taxonomy.find(value.get<std::string>());
    if (id < 0)
      fail(path, "class map: label " + key + " maps to '" + value.get<std::string>() +
                     "', which the taxonomy does not have (give --taxonomy with it, or null to leave it unlabelled)");
    map.classes[label] = id;
  }
  return map;
}

std::vector<int32_t> map_labels(const ClassMap& map, const std::vector<double>& values, const std::string& cloud,
                                const std::string& field) {
  std::vector<int32_t> out(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (!(std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9e15))
      fail(cloud, "point " + std::to_string(i) + " has " + field + " = " + std::to_string(v) + ": not an integer label");
    const auto it = map.classes.find(static_cast<int64_t>(v));
    if (it == map.classes.end())
      fail(cloud, field + " value " + std::to_string(static_cast<int64_t>(v)) + " (point " + std::to_string(i) +
                      ") is not in the class map " + map.file + ": add it there (null leaves its points unlabelled)");
    out[i] = it->second;
  }
  return out;
}

}  // namespace cls
