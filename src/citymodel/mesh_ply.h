#pragma once
// Binary little-endian PLY of a SemanticMesh for inspection in any viewer (MeshLab, CloudCompare,
// Blender). Vertices: float x y z, in the local frame (source CRS minus the origin, given in a
// "comment origin x y z" line) or, with a CityTransform, in the scene frame. Faces: vertex_indices
// (uchar count, int indices), uchar red green blue (taxonomy colour of the face's level-1 class),
// int class_l1 class_l2 class_l3 (class ids per level, -1 none) and int building (index into
// SemanticMesh::buildings, -1 none).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "citymodel/city_transform.h"
#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"
#include "core/math.h"

namespace cls {

// Written atomically; `transform` nullptr keeps the local frame.
void write_mesh_ply(const std::string& path, const SemanticMesh& mesh, const Taxonomy& taxonomy,
                    const CityTransform* transform);

// What write_mesh_ply wrote, as far as a viewer needs it: vertices, triangles and face colours.
struct ColouredMesh {
  std::vector<Vec3f> vertices;
  std::vector<std::array<int32_t, 3>> triangles;
  std::vector<std::array<uint8_t, 3>> colours;  // per triangle
};
// cls::Error naming the file when it is not a PLY of write_mesh_ply's layout, is truncated, or a
// face indexes beyond the vertices, or a vertex is not finite.
ColouredMesh read_mesh_ply(const std::string& path);
// The same from the file's bytes; `path` names it in errors.
ColouredMesh parse_mesh_ply(std::string_view bytes, const std::string& path);

}  // namespace cls
