#pragma once
// Accumulates semantic entities and polygons from a city-model reader and produces a SemanticMesh.
// Shared by the CityGML and CityJSON readers, so both triangulate and label identically.
#include <array>
#include <string>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"

namespace cls {

using Ring = std::vector<std::array<double, 3>>;  // source CRS coordinates, double precision

class MeshBuilder {
 public:
  explicit MeshBuilder(const Taxonomy& taxonomy);

  // Adds a semantic object; returns its index. `parent` is an earlier entity or -1.
  int add_entity(int level, int class_id, int parent, const std::string& source_id);

  // Adds one planar polygon: rings[0] is the exterior, the rest are holes (either orientation).
  // Triangulated with the GLU tesselator (odd winding rule). `face_class` is the class of the
  // face itself; `entity` is the innermost entity the face belongs to (its chain of parents gives
  // the other levels). Polygons whose `polygon_id` was already added are skipped (a solid that
  // references its boundary surfaces by xlink must not double the triangles): returns false then.
  // Degenerate polygons (fewer than 3 distinct points, zero area) add nothing and are counted.
  // Throws cls::Error for non-finite coordinates.
  bool add_polygon(const std::vector<Ring>& rings, int face_class, int entity, const std::string& polygon_id);

  // Subtracts a local origin (the bounding box minimum, rounded down to whole units), computes
  // tri_level_class (see SemanticMesh) and returns the mesh. The builder is empty afterwards.
  SemanticMesh finish();

  size_t degenerate_polygons() const { return degenerate_; }

 private:
  const Taxonomy& taxonomy_;
  SemanticMesh mesh_;
  std::vector<std::array<double, 3>> vertices_abs_;
  std::vector<std::string> seen_ids_sorted_;  // implementation detail; may change
  size_t degenerate_ = 0;
};

}  // namespace cls
