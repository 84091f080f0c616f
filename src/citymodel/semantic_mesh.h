#pragma once
// The city model as one triangle mesh with per-face semantics on three levels (paper 3.1).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cls {

// A semantic object of the city model: an opening (level 1), a boundary surface or installation
// (level 2) or a building / building part (level 3).
struct SemanticEntity {
  int level = 0;          // 1, 2 or 3
  int class_id = -1;      // index into Taxonomy::classes
  int parent = -1;        // enclosing entity (opening -> surface -> building), -1 for none
  std::string source_id;  // gml:id or CityJSON object id / semantic-surface index, for tracing
};

struct SemanticMesh {
  // Provenance.
  std::string source_path;
  std::string format;   // "CityGML" or "CityJSON" (CityJSONSeq is reported as "CityJSON")
  std::string version;  // "1.0", "2.0", "3.0", "1.1", ...
  std::string crs;      // srsName / referenceSystem as written in the file ("" if none)
  int lod = 0;          // the LoD the geometry was taken from

  // Vertices are in the source CRS minus `origin` (parsed in double; the origin keeps
  // float32 precise later). Source coordinate = vertex + origin.
  std::array<double, 3> origin{0, 0, 0};
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;

  // Per triangle:
  std::vector<int32_t> tri_class;                 // class of the face itself (window, wall, ...)
  std::vector<std::array<int32_t, 3>> tri_entity; // entity at level 1, 2, 3 (index into entities; -1 none)
  std::vector<int32_t> tri_polygon;               // index into polygon_ids (source polygon)
  // Class per level, the paper's C^l before projection (-1 = none):
  //  level 1: the opening's class, or the face's own class where the face is in no opening
  //           (the subpart fallback: a plain wall pixel stays "wall" at the subpart level);
  //  level 2: the class of the boundary surface (a window inherits its wall's class);
  //  level 3: the building class.
  std::vector<std::array<int32_t, 3>> tri_level_class;

  std::vector<std::string> polygon_ids;  // gml:id of the source polygon, or "<object id>/<surface index>"
  std::vector<SemanticEntity> entities;

  // Building (level-3 entity) index of each building, in entity order, for building.png.
  std::vector<int32_t> buildings;

  size_t num_triangles() const { return triangles.size(); }
};

}  // namespace cls
