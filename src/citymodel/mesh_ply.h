#pragma once
// Binary little-endian PLY of a SemanticMesh for inspection in any viewer (MeshLab, CloudCompare,
// Blender). Vertices: float x y z, in the local frame (source CRS minus the origin, given in a
// "comment origin x y z" line) or, with a CityTransform, in the scene frame. Faces: vertex_indices
// (uchar count, int indices), uchar red green blue (taxonomy colour of the face's level-1 class),
// int class_l1 class_l2 class_l3 (class ids per level, -1 none) and int building (index into
// SemanticMesh::buildings, -1 none).
#include <string>

#include "citymodel/city_transform.h"
#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"

namespace cls {

// Written atomically; `transform` nullptr keeps the local frame.
void write_mesh_ply(const std::string& path, const SemanticMesh& mesh, const Taxonomy& taxonomy,
                    const CityTransform* transform);

}  // namespace cls
