#pragma once
// The city objects of a semantic mesh as a flat table: every entity (opening, boundary surface,
// building) with its gml:id / CityJSON id, class and enclosing object. The label maps' object.npy
// holds indices into it (raycast), the language model keeps one per Gaussian (provenance), and a
// query answers with its rows. Written as objects.json beside the label maps and in the model.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"

namespace cls {

struct CityObject {
  std::string id;        // gml:id or CityJSON id (SemanticEntity::source_id)
  int level = 0;         // 1 opening, 2 surface / installation, 3 building / building part
  int class_id = -1;     // taxonomy class, -1 none
  int32_t parent = -1;   // enclosing object (an earlier row; a BuildingPart's is its Building or part), -1 none
};

struct CityObjects {
  std::string source;                    // the city model file
  std::vector<std::string> class_names;  // taxonomy class names by id
  std::vector<CityObject> objects;       // index = SemanticMesh entity index

  // The object that answers for `object` at a label level, as the label maps do: the first of the
  // object and its ancestors whose level is >= `level` (a window at level 2 is its wall; a plain
  // wall at level 1 is the wall itself; a building or part without a finer object answers for
  // itself), and on level 3 the whole Building (the outermost of the building / part chain, as
  // building.png). -1 for -1 or when no ancestor reaches that level.
  int32_t at_level(int32_t object, int level) const;
  // The BuildingPart `object` lies in (the innermost level-3 object of its chain, the object itself if
  // it is a part); -1 where that is the whole building or there is none.
  int32_t part_of(int32_t object) const;
  std::string class_name(int32_t object) const;  // "" for none

  nlohmann::json to_json() const;
  // cls::Error naming `file` on a malformed table (missing fields; a parent out of range, after its
  // child or on a finer level; a class out of range).
  static CityObjects from_json(const nlohmann::json& j, const std::string& file);
};

// The table of a mesh: one row per SemanticMesh entity, in entity order. std::logic_error (exit 3:
// a bug, not bad input) when the mesh breaks the rules from_json checks.
CityObjects city_objects(const SemanticMesh& mesh, const Taxonomy& taxonomy);

// The per-triangle object of a mesh for the label maps: the triangle's opening, else its surface,
// else its building (the finest entity; -1 where the triangle has none).
std::vector<int32_t> finest_object_of_triangles(const SemanticMesh& mesh);

// Building index (into mesh.buildings) of every entity: its own, or that of the nearest enclosing
// building (a BuildingPart belongs to its Building); -1 for none. cls::Error naming the model when
// mesh.buildings refers to an entity that does not exist.
std::vector<int32_t> building_of_entities(const SemanticMesh& mesh);
// The same for every triangle, from its level-3 entity: the building.png of the label maps.
std::vector<int32_t> building_of_triangles(const SemanticMesh& mesh);

void write_city_objects(const std::filesystem::path& path, const CityObjects& objects);  // atomic
CityObjects read_city_objects(const std::filesystem::path& path);

}  // namespace cls
