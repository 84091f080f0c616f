#include "raycast/label_maps.h"

#include <limits>

#include "citymodel/city_objects.h"
#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

constexpr size_t kMaxLabel = std::numeric_limits<uint16_t>::max() - 1;  // stored as label + 1

}  // namespace

std::vector<uint8_t> opening_priority(const SemanticMesh& mesh) {
  std::vector<uint8_t> priority(mesh.num_triangles(), 0);
  for (size_t t = 0; t < mesh.tri_entity.size() && t < priority.size(); ++t)
    priority[t] = mesh.tri_entity[t][0] >= 0 ? 1 : 0;
  return priority;
}

LabelTable::LabelTable(const SemanticMesh& mesh) {
  const size_t n = mesh.num_triangles();
  if (mesh.tri_level_class.size() != n || mesh.tri_entity.size() != n)
    throw Error(cat(mesh.source_path, ": semantic mesh has ", n, " triangles but ", mesh.tri_level_class.size(),
                    " level classes and ", mesh.tri_entity.size(), " entity triples"));
  if (mesh.buildings.size() > kMaxLabel)
    throw Error(cat(mesh.source_path, ": ", mesh.buildings.size(), " buildings; building.png (uint16) holds at most ",
                    kMaxLabel));
  const std::vector<int32_t> building = building_of_triangles(mesh);
  const std::vector<int32_t> object = finest_object_of_triangles(mesh);
  entries_.resize(n);
  for (size_t t = 0; t < n; ++t) {
    Entry& e = entries_[t];
    for (int l = 0; l < 3; ++l) {
      const int32_t c = mesh.tri_level_class[t][l];
      if (c >= 0 && static_cast<size_t>(c) >= kMaxLabel)
        throw Error(cat(mesh.source_path, ": class id ", c, " does not fit a uint16 label map"));
      e.level[l] = c < 0 ? 0 : static_cast<uint16_t>(c + 1);
    }
    e.building = static_cast<uint16_t>(building[t] + 1);  // 0 for none
    e.object = object[t];
  }
}

void LabelTable::fill(const std::vector<RayHit>& hits, int width, int height, LabelMaps& out) const {
  const size_t n = static_cast<size_t>(width) * height;
  if (hits.size() != n) throw Error(cat("label maps: ", hits.size(), " hits for a ", width, "x", height, " view"));
  out.width = width;
  out.height = height;
  for (auto& l : out.level) l.resize(n);
  out.building.resize(n);
  out.object.resize(n);
  out.coverage.resize(n);
  out.depth.resize(n);
  // Raw pointers: the uint8_t coverage stores may alias anything, so through the vectors every
  // store would force the compiler to reload all data pointers.
  const RayHit* in = hits.data();
  const Entry* table = entries_.data();
  const size_t entries = entries_.size();
  uint16_t *l1 = out.level[0].data(), *l2 = out.level[1].data(), *l3 = out.level[2].data();
  uint16_t* building = out.building.data();
  int32_t* object = out.object.data();
  uint8_t* coverage = out.coverage.data();
  float* depth = out.depth.data();
  const Entry none{{0, 0, 0}, 0, -1};
#pragma omp parallel for schedule(static)
  for (int64_t p = 0; p < static_cast<int64_t>(n); ++p) {
    const RayHit& h = in[p];
    const bool hit = h.prim < entries;  // kNoHit is never a valid index
    const Entry& e = hit ? table[h.prim] : none;
    l1[p] = e.level[0];
    l2[p] = e.level[1];
    l3[p] = e.level[2];
    building[p] = e.building;
    object[p] = e.object;
    coverage[p] = (e.level[0] | e.level[1] | e.level[2]) ? 255 : 0;
    depth[p] = hit ? h.depth : 0.0f;
  }
}

}  // namespace cls
