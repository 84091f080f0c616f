#pragma once
// Semantic classes of the city model and how they map onto the paper's three levels
// (section 3.1: l = 1 subpart / window, door; l = 2 part / wall, roof, ...; l = 3 whole / building).
// Loaded from JSON (data/taxonomy.json is the shipped default; users may pass their own).
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cls {

struct SemanticClass {
  std::string name;                       // "window", "wall", ...
  int level = 2;                          // 1, 2 or 3
  std::vector<std::string> source_types;  // CityGML/CityJSON type names mapped to it: "Window", "WallSurface", ...
  std::vector<std::string> prompts;       // text prompts; prompts[0] is the default (paper: "a window on a building facade")
  std::array<unsigned char, 3> color{};   // preview / PLY colour (RGB)
};

struct Taxonomy {
  std::vector<SemanticClass> classes;  // class id = index; label maps store id + 1 (0 = no label)

  // The shipped default (data/taxonomy.json, compiled in so the binary works from any directory).
  static Taxonomy builtin();
  // Reads a user taxonomy; cls::Error naming the file on malformed JSON or missing fields.
  static Taxonomy load(const std::string& path);

  // Class id of a CityGML/CityJSON type name ("WallSurface", "Window", "Building"...), if mapped.
  std::optional<int> class_of_type(const std::string& type) const;
  // Class id by class name ("wall"); -1 if absent.
  int find(const std::string& name) const;
  // legend.json content: [{"id":k,"name":...,"level":...,"color":[r,g,b],"prompts":[...]}, ...]
  std::string legend_json() const;
  // A taxonomy recorded as its legend (what the features stage and language training write): class
  // order, names, levels, prompts and colours; the source types are not recorded (not needed to encode
  // text or colour a map). cls::Error naming `file` on malformed JSON or out-of-order ids.
  static Taxonomy from_legend(const std::string& legend_json, const std::string& file);
};

}  // namespace cls
