#include "citymodel/mesh_stats.h"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace cls {

namespace {
double triangle_area(const SemanticMesh& mesh, const std::array<uint32_t, 3>& t) {
  const auto& a = mesh.vertices[t[0]];
  const auto& b = mesh.vertices[t[1]];
  const auto& c = mesh.vertices[t[2]];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}
}  // namespace

MeshStats compute_mesh_stats(const SemanticMesh& mesh, const Taxonomy& taxonomy) {
  MeshStats s;
  s.format = mesh.format;
  s.version = mesh.version;
  s.crs = mesh.crs;
  s.lod = mesh.lod;
  s.origin = mesh.origin;
  s.buildings = mesh.buildings.size();
  s.vertices = mesh.vertices.size();
  s.triangles = mesh.num_triangles();

  std::vector<ClassStats> per_class(taxonomy.classes.size());
  for (size_t c = 0; c < per_class.size(); ++c) per_class[c].name = taxonomy.classes[c].name;
  for (size_t t = 0; t < mesh.num_triangles(); ++t) {
    const int c = mesh.tri_class[t];
    if (c < 0 || c >= static_cast<int>(per_class.size())) continue;
    ++per_class[c].triangles;
    per_class[c].area += triangle_area(mesh, mesh.triangles[t]);
  }
  for (const SemanticEntity& e : mesh.entities)
    if (e.class_id >= 0 && e.class_id < static_cast<int>(per_class.size())) ++per_class[e.class_id].objects;
  for (ClassStats& c : per_class)
    if (c.triangles > 0 || c.objects > 0) s.classes.push_back(std::move(c));
  return s;
}

std::string mesh_stats_json(const MeshStats& s) {
  nlohmann::ordered_json classes = nlohmann::ordered_json::object();
  for (const ClassStats& c : s.classes)
    classes[c.name] = {{"triangles", c.triangles}, {"area", c.area}, {"objects", c.objects}};
  const nlohmann::ordered_json j = {{"format", s.format},     {"version", s.version},
                                    {"crs", s.crs},           {"lod", s.lod},
                                    {"origin", s.origin},     {"buildings", s.buildings},
                                    {"vertices", s.vertices}, {"triangles", s.triangles},
                                    {"classes", classes}};
  // Names come from the input file: replace invalid UTF-8 rather than fail on it.
  return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::string mesh_stats_table(const MeshStats& s) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "format     %s %s, LoD %d\n", s.format.c_str(), s.version.c_str(), s.lod);
  out += line;
  out += "crs        " + (s.crs.empty() ? std::string("(none)") : s.crs) + "\n";
  std::snprintf(line, sizeof line, "origin     %.3f %.3f %.3f\n", s.origin[0], s.origin[1], s.origin[2]);
  out += line;
  std::snprintf(line, sizeof line, "buildings  %zu\nvertices   %zu\ntriangles  %zu\n\n", s.buildings, s.vertices,
                s.triangles);
  out += line;
  std::snprintf(line, sizeof line, "%-16s %10s %10s %14s\n", "class", "objects", "triangles", "area");
  out += line;
  for (const ClassStats& c : s.classes) {
    std::snprintf(line, sizeof line, "%-16s %10zu %10zu %14.3f\n", c.name.c_str(), c.objects, c.triangles, c.area);
    out += line;
  }
  return out;
}

}  // namespace cls
