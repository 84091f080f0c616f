#pragma once
// CityGML 1.0 / 2.0 / 3.0 buildings -> SemanticMesh.
//
// Elements are matched by local name, so any namespace prefix works. Building and BuildingPart are
// level-3 entities; boundary surfaces (WallSurface, RoofSurface, ...) and BuildingInstallation /
// BuildingConstructiveElement level 2; openings (Window, Door in 1.0/2.0, WindowSurface /
// DoorSurface under con:fillingSurface in 3.0) level 1. Any other type the taxonomy maps becomes an
// entity of its class's level. Geometry is read from the lodN* properties of the selected LoD;
// geometry of a building outside its semantic surfaces (e.g. an lod2Solid alone) is class
// "surface". xlink:href inside geometry is resolved; polygons reached twice (a solid referencing
// its boundary surfaces) are added once, with the class of the semantic surface. City objects
// other than buildings are skipped (reported with -v).
//
// Errors (cls::Error naming the file, with the line where known): malformed XML (pugixml's
// description and position), no CityGML namespace, a gml:id that is not an XML ID (e.g. starts with
// a digit) or is duplicated, a dangling xlink:href, a geometry xlink to another file, unparsable or
// non-finite coordinates, rings of fewer than 3 points, a polygon without exterior ring, nesting
// deeper than 256 levels, no building geometry at the requested LoD. Zero-area polygons are
// skipped and counted (logged), as MeshBuilder does.
#include <cstddef>
#include <string>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"

namespace cls {

// `lod`: 1..4 reads that LoD; 0 reads each building at the highest LoD (1..4) it has.
SemanticMesh read_citygml(const std::string& path, const Taxonomy& taxonomy, int lod);

// The same from memory; `name` stands for the file in error messages and SemanticMesh::source_path.
SemanticMesh read_citygml_buffer(const char* data, size_t size, const std::string& name,
                                 const Taxonomy& taxonomy, int lod);

}  // namespace cls
