#pragma once
// A class map: the label values of a user's labelled point cloud (ZAHA's LoFG3 codes, an MLS campaign's
// classes) -> the taxonomy's classes, so that ground truth labelled in another scheme is scored against
// ours. A JSON file (data/class-maps/ holds the shipped ones; docs/evaluation.md):
//   {"name": "ZAHA LoFG3", "classes": {"0": "wall", "1": "window", "11": null, ...}}
// null leaves a label's points unlabelled (not scored); a label the map does not list is an error.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "citymodel/taxonomy.h"

namespace cls {

struct ClassMap {
  std::string file;                   // where it was read (errors name it)
  std::string name;                   // "ZAHA LoFG3"
  std::map<int64_t, int32_t> classes;  // label value -> taxonomy class id, -1 = unlabelled
};

// cls::Error naming the file on malformed JSON, a key that is not an integer, or a class name the
// taxonomy does not have.
ClassMap read_class_map(const std::string& path, const Taxonomy& taxonomy);

// The taxonomy class of every label value. A value that is not an integer or that the map does not list
// is a cls::Error naming the cloud (`cloud`), its field and the value, and the map.
std::vector<int32_t> map_labels(const ClassMap& map, const std::vector<double>& values, const std::string& cloud,
                                const std::string& field);

}  // namespace cls
