#pragma once
// CityJSON 1.0 / 1.1 / 2.0 documents and CityJSONSeq (JSON lines) -> SemanticMesh.
//
// Mapping (see data/taxonomy.json):
//  - a CityObject whose type maps to a level-3 class (Building, BuildingPart) is a level-3 entity
//    under the nearest level-3 object up its "parents" chain (building -> part -> part ...); a cycle
//    of "parents" is an error naming the object;
//  - other mapped CityObjects (BuildingInstallation, ...) become an entity of their class under
//    the building or part they lie in; objects of unmapped types (Road, TINRelief, ...) are skipped;
//  - semantic surfaces (geometry "semantics") become entities: walls, roofs, ... at level 2 under
//    the building; Window/Door surfaces at level 1 under the surface named by their "parent"
//    index; faces without semantics get the class "surface";
//  - LoD: `lod` 1, 2 or 3 takes the geometries whose LoD ("2", "2.2", ...) has that integer part,
//    0 takes the highest LoD of each object. Of several geometries of one object at the chosen
//    integer LoD (1.2 and 1.3), only the highest is used, so copies do not overlap;
//  - polygon ids "<object id>/<geometry index>/<surface index>" (surface index counted through
//    the geometry's boundaries in order).
// Every problem with the input is a cls::Error naming the file (and the object where useful).
#include <string>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"

namespace cls {

// Reads a CityJSON document or a CityJSONSeq file (detected by content).
SemanticMesh read_cityjson(const std::string& path, const Taxonomy& taxonomy, int lod);

// Buffer-level entry points (tests, fuzzer); `name` is the file name used in error messages.
SemanticMesh parse_cityjson(const std::string& text, const std::string& name, const Taxonomy& taxonomy, int lod);
SemanticMesh parse_cityjson_seq(const std::string& text, const std::string& name, const Taxonomy& taxonomy,
                                int lod);

// True when `text` is a CityJSONSeq stream: a first line that is a complete JSON object
// (the CityJSON header) followed by more non-empty lines. A pretty-printed or single-line
// CityJSON document is not.
bool is_cityjson_seq(const std::string& text);

}  // namespace cls
