#pragma once
// Independent area bookkeeping for tests: computed in double straight from the mesh triangles.
#include <cmath>
#include <map>
#include <string>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"

namespace cls::test {

inline double triangle_area(const SemanticMesh& m, size_t t) {
  const auto& a = m.vertices[m.triangles[t][0]];
  const auto& b = m.vertices[m.triangles[t][1]];
  const auto& c = m.vertices[m.triangles[t][2]];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

inline double total_area(const SemanticMesh& m) {
  double sum = 0;
  for (size_t t = 0; t < m.num_triangles(); ++t) sum += triangle_area(m, t);
  return sum;
}

// Area per class name of tri_class (the face's own class).
inline std::map<std::string, double> area_by_class(const SemanticMesh& m, const Taxonomy& tax) {
  std::map<std::string, double> out;
  for (size_t t = 0; t < m.num_triangles(); ++t) out[tax.classes[m.tri_class[t]].name] += triangle_area(m, t);
  return out;
}

inline std::map<std::string, size_t> triangles_by_class(const SemanticMesh& m, const Taxonomy& tax) {
  std::map<std::string, size_t> out;
  for (size_t t = 0; t < m.num_triangles(); ++t) ++out[tax.classes[m.tri_class[t]].name];
  return out;
}

}  // namespace cls::test
