#pragma once
// Accumulates semantic entities and polygons from a city-model reader and produces a SemanticMesh.
// Shared by the CityGML and CityJSON readers, so both triangulate and label identically.
#include <array>
#include <string>
#include <unordered_set>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"

namespace cls {

using Ring = std::vector<std::array<double, 3>>;  // source CRS coordinates, double precision

class MeshBuilder {
 public:
  explicit MeshBuilder(const Taxonomy& taxonomy);

  // Adds a semantic object; returns its index. `parent` is an earlier entity or -1, on the same or a
  // coarser level (cls::Error naming both objects otherwise).
  int add_entity(int level, int class_id, int parent, const std::string& source_id);

  // Adds one planar polygon: rings[0] is the exterior, the rest are holes (either orientation).
  // Triangulated with the GLU tesselator (odd winding rule). `face_class` is the class of the
  // face itself; `entity` is the innermost entity the face belongs to (its chain of parents gives
  // the other levels). Polygons whose `polygon_id` was already added are skipped (a solid that
  // references its boundary surfaces by xlink must not double the triangles): returns false then.
  // Degenerate polygons (fewer than 3 distinct points, zero area) add nothing and are counted.
  // Throws cls::Error for non-finite coordinates.
  bool add_polygon(const std::vector<Ring>& rings, int face_class, int entity, const std::string& polygon_id);

  // tri_entity[0..2] are the nearest level-1 and level-2 entities in the face's parent chain and
  // the outermost level-3 entity (the Building, not a BuildingPart): building.png and
  // SemanticMesh::buildings index whole buildings, the paper's level 3.
  // Subtracts a local origin (the bounding box minimum, rounded down to whole units), computes
  // tri_level_class (see SemanticMesh) and returns the mesh. The builder is empty afterwards.
  SemanticMesh finish();

  size_t degenerate_polygons() const { return degenerate_; }

 private:
  // Class per level of a face (see SemanticMesh::tri_level_class).
  std::array<int32_t, 3> level_classes(int face_class, const std::array<int32_t, 3>& chain) const;

  const Taxonomy& taxonomy_;
  SemanticMesh mesh_;
  std::vector<std::array<double, 3>> vertices_abs_;
  std::unordered_set<std::string> seen_polygon_ids_;
  size_t degenerate_ = 0;
};

}  // namespace cls
