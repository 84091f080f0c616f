#include "citymodel/taxonomy.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/log.h"

namespace cls {

extern const char* const kBuiltinTaxonomyJson;  // generated from data/taxonomy.json by CMake

namespace {

using nlohmann::json;

std::vector<std::string> string_list(const json& c, const char* key, const std::string& where,
                                     const std::string& source) {
  std::vector<std::string> out;
  if (!c.contains(key)) return out;
  const json& list = c.at(key);
  if (!list.is_array()) fail(source, cat(where, ": \"", key, "\" must be an array of strings"));
  for (const json& s : list) {
    if (!s.is_string()) fail(source, cat(where, ": \"", key, "\" must be an array of strings"));
    out.push_back(s.get<std::string>());
  }
  return out;
}

SemanticClass parse_class(const json& c, size_t index, const std::string& source) {
  const std::string where = cat("class #", index);
  if (!c.is_object()) fail(source, where + ": must be an object");
  SemanticClass cls;
  if (!c.contains("name") || !c.at("name").is_string() || c.at("name").get<std::string>().empty())
    fail(source, where + ": missing \"name\" (a non-empty string)");
  cls.name = c.at("name").get<std::string>();
  const std::string named = cat(where, " \"", cls.name, "\"");
  if (!c.contains("level") || !c.at("level").is_number_integer())
    fail(source, named + ": missing \"level\" (1, 2 or 3)");
  cls.level = c.at("level").get<int>();
  if (cls.level < 1 || cls.level > 3) fail(source, cat(named, ": level ", cls.level, " is not 1, 2 or 3"));
  cls.source_types = string_list(c, "source_types", named, source);
  cls.prompts = string_list(c, "prompts", named, source);
  if (cls.prompts.empty()) cls.prompts.push_back(cls.name);  // prompts[0] must exist: the class name is the plainest prompt
  if (c.contains("color")) {
    const json& rgb = c.at("color");
    if (!rgb.is_array() || rgb.size() != 3) fail(source, named + ": \"color\" must be [r, g, b]");
    for (int k = 0; k < 3; ++k) {
      if (!rgb[k].is_number_integer() || rgb[k].get<int>() < 0 || rgb[k].get<int>() > 255)
        fail(source, named + ": \"color\" components must be integers 0..255");
      cls.color[k] = static_cast<unsigned char>(rgb[k].get<int>());
    }
  } else {
    cls.color = {128, 128, 128};
  }
  return cls;
}

// `source` names the origin of the text in error messages (a path, or "<builtin taxonomy>").
Taxonomy parse_taxonomy(const std::string& text, const std::string& source) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    fail(source, cat("malformed JSON: ", e.what()));
  }
  if (!root.is_object() || !root.contains("classes") || !root.at("classes").is_array())
    fail(source, "a taxonomy needs a \"classes\" array");
  Taxonomy taxonomy;
  std::set<std::string> names, types;
  for (size_t i = 0; i < root.at("classes").size(); ++i) {
    SemanticClass c = parse_class(root.at("classes")[i], i, source);
    if (!names.insert(c.name).second) fail(source, cat("duplicate class name \"", c.name, "\""));
    for (const std::string& t : c.source_types)
      if (!types.insert(t).second) fail(source, cat("source type \"", t, "\" is mapped to more than one class"));
    taxonomy.classes.push_back(std::move(c));
  }
  if (taxonomy.classes.empty()) fail(source, "the taxonomy has no classes");
  return taxonomy;
}

}  // namespace

Taxonomy Taxonomy::builtin() { return parse_taxonomy(kBuiltinTaxonomyJson, "<builtin taxonomy>"); }

Taxonomy Taxonomy::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open taxonomy file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) fail(path, "cannot read taxonomy file");
  return parse_taxonomy(text.str(), path);
}

std::optional<int> Taxonomy::class_of_type(const std::string& type) const {
  for (size_t k = 0; k < classes.size(); ++k)
    for (const std::string& t : classes[k].source_types)
      if (t == type) return static_cast<int>(k);
  return std::nullopt;
}

int Taxonomy::find(const std::string& name) const {
  for (size_t k = 0; k < classes.size(); ++k)
    if (classes[k].name == name) return static_cast<int>(k);
  return -1;
}

std::string Taxonomy::legend_json() const {
  json legend = json::array();
  for (size_t k = 0; k < classes.size(); ++k) {
    const SemanticClass& c = classes[k];
    legend.push_back({{"id", k},
                      {"name", c.name},
                      {"level", c.level},
                      {"color", {c.color[0], c.color[1], c.color[2]}},
                      {"prompts", c.prompts}});
  }
  return legend.dump(2) + "\n";
}

Taxonomy Taxonomy::from_legend(const std::string& legend_json, const std::string& file) {
  Taxonomy t;
  try {
    const json legend = json::parse(legend_json);
    if (!legend.is_array()) fail(file, "taxonomy: the legend is not an array of classes");
    for (size_t i = 0; i < legend.size(); ++i) {
      const json& c = legend.at(i);
      if (c.value("id", static_cast<int>(i)) != static_cast<int>(i))
        fail(file, "taxonomy: class " + std::to_string(i) + " has id " + c["id"].dump());
      SemanticClass sc;
      sc.name = c.at("name").get<std::string>();
      sc.level = c.value("level", 2);
      sc.prompts = c.value("prompts", std::vector<std::string>{});
      if (c.contains("color")) sc.color = c["color"].get<std::array<unsigned char, 3>>();
      t.classes.push_back(std::move(sc));
    }
  } catch (const json::exception& e) {
    fail(file, std::string("taxonomy: ") + e.what());
  }
  return t;
}

}  // namespace cls
