#pragma once
// Summary of a SemanticMesh for `citymodel stats`: counts and areas per semantic class.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"

namespace cls {

struct ClassStats {
  std::string name;
  size_t triangles = 0;  // faces whose own class (tri_class) is this class
  double area = 0;       // their area in square source units, summed in double
  size_t objects = 0;    // semantic entities of this class (15 windows, 6 doors, ...)
};

struct MeshStats {
  std::string format, version, crs;
  int lod = 0;
  std::array<double, 3> origin{0, 0, 0};
  size_t buildings = 0;
  size_t vertices = 0;
  size_t triangles = 0;
  std::vector<ClassStats> classes;  // taxonomy order; only classes with triangles or objects
};

MeshStats compute_mesh_stats(const SemanticMesh& mesh, const Taxonomy& taxonomy);

// Exactly one JSON object (one line):
// {"format","version","crs","lod","origin","buildings","vertices","triangles",
//  "classes":{"<name>":{"triangles","area","objects"}}}
std::string mesh_stats_json(const MeshStats& stats);
// A readable table for people.
std::string mesh_stats_table(const MeshStats& stats);

}  // namespace cls
