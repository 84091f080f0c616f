#pragma once
// Per-view label maps from one raycast (paper section 3.1): the class maps C^1, C^2, C^3, the
// building instance map, the city-object map, the coverage mask M and the depth of the first hit.
//
// The paper defines C^l(v) as the class of the front-most polygon at level l, and M(v) = 1 where
// any level is valid. The mesh carries one class per level for every triangle
// (SemanticMesh::tri_level_class), so a single cast yields all three maps:
//  - level 1 (subpart): the opening's class where the first hit is a window or door; on a surface
//    without an opening, the surface's own class (the subpart fallback: the paper's equations
//    would leave such pixels invalid at level 1, which would make most of a facade unsupervised
//    at the finest level; a plain wall is its own finest part);
//  - level 2 (part): the boundary surface's class; a window pixel carries its wall's class;
//  - level 3 (whole): the building class.
// Coverage is 255 wherever any level has a label, which with the fallback means wherever the
// first hit is a classified triangle. A hit on an unclassified triangle still occludes what lies
// behind it (the first hit decides), it just carries no label.
#include <array>
#include <cstdint>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "raycast/raycaster.h"

namespace cls {

struct LabelMaps {
  int width = 0, height = 0;                   // all maps are row-major, width * height
  std::array<std::vector<uint16_t>, 3> level;  // level[l - 1]: 0 = no label, k = taxonomy class k - 1
  std::vector<uint16_t> building;              // index into SemanticMesh::buildings + 1; 0 = none
  std::vector<int32_t> object;                 // the first hit's finest city object (city_objects.h); -1 = none
  std::vector<uint8_t> coverage;               // 255 where any level has a label (M = 1), else 0
  std::vector<float> depth;                    // camera z-depth of the first hit; 0 where nothing is hit
};

// Raycaster priorities for a mesh: 1 for triangles of an opening (a level-1 entity), 0 otherwise,
// so that an opening wins over the wall it lies on.
std::vector<uint8_t> opening_priority(const SemanticMesh& mesh);

// The per-triangle labels of a mesh, looked up once, so a view costs one table read per pixel.
class LabelTable {
 public:
  // cls::Error if a label does not fit the uint16 maps (more than 65534 classes or buildings).
  explicit LabelTable(const SemanticMesh& mesh);

  // Fills `out` from the hits of one cast_view (width * height, row-major). Multithreaded.
  void fill(const std::vector<RayHit>& hits, int width, int height, LabelMaps& out) const;

  size_t num_triangles() const { return entries_.size(); }

 private:
  struct Entry {
    std::array<uint16_t, 3> level;
    uint16_t building;
    int32_t object;  // finest_object_of_triangles
  };
  std::vector<Entry> entries_;
};

}  // namespace cls
