#include "citymodel/mesh_builder.h"

#include <GL/glu.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/error.h"
#include "core/log.h"
#include "core/math.h"

namespace cls {

namespace {

// No real city model has coordinates beyond this (in metres, feet or millimetres); larger values
// are corrupt input and would overflow the float conversion later.
constexpr double kMaxCoordinate = 1e12;

using Point = std::array<double, 3>;

Vec3d vec(const Point& p) { return {p[0], p[1], p[2]}; }

// A ring without repeated consecutive points and without the closing copy of the first point.
Ring cleaned(const Ring& ring) {
  Ring out;
  out.reserve(ring.size());
  for (const Point& p : ring)
    if (out.empty() || p != out.back()) out.push_back(p);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

// Newell's method: twice the vector area of the ring, robust for non-convex and slightly
// non-planar rings. Its direction is the ring's normal (counter-clockwise seen from its tip).
Vec3d newell_normal(const Ring& ring, const Point& ref) {
  Vec3d n{0, 0, 0};
  for (size_t i = 0; i < ring.size(); ++i) {
    const Vec3d a = vec(ring[i]) - vec(ref), b = vec(ring[(i + 1) % ring.size()]) - vec(ref);
    n = n + cross(a, b);
  }
  return n;
}

// State of one GLU tessellation: vertices are indices into `points`, local to `ref`.
struct Tessellation {
  std::vector<Point> points;  // ring points, then combine (intersection) points
  std::vector<std::array<uint32_t, 3>> triangles;
  std::array<uint32_t, 3> pending{};
  int num_pending = 0;
  GLenum error = 0;
};

void* index_as_data(size_t i) { return reinterpret_cast<void*>(static_cast<uintptr_t>(i)); }
uint32_t data_as_index(void* d) { return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(d)); }

// With an edge-flag callback registered GLU emits independent triangles only (GL_TRIANGLES).
void GLAPIENTRY on_begin(GLenum, void* t) { static_cast<Tessellation*>(t)->num_pending = 0; }
void GLAPIENTRY on_edge_flag(GLboolean, void*) {}
void GLAPIENTRY on_vertex(void* vertex, void* t) {
  Tessellation& tess = *static_cast<Tessellation*>(t);
  tess.pending[tess.num_pending++] = data_as_index(vertex);
  if (tess.num_pending == 3) {
    tess.triangles.push_back(tess.pending);
    tess.num_pending = 0;
  }
}
void GLAPIENTRY on_combine(GLdouble coords[3], void*[4], GLfloat[4], void** out, void* t) {
  Tessellation& tess = *static_cast<Tessellation*>(t);
  tess.points.push_back({coords[0], coords[1], coords[2]});
  *out = index_as_data(tess.points.size() - 1);
}
void GLAPIENTRY on_error(GLenum error, void* t) { static_cast<Tessellation*>(t)->error = error; }
void GLAPIENTRY on_end(void*) {}

using TessPtr = std::unique_ptr<GLUtesselator, void (*)(GLUtesselator*)>;

// Triangulates rings (local coordinates) lying in the plane with normal `normal`, odd winding rule:
// holes may have either orientation. Triangles are counter-clockwise around `normal`.
Tessellation tessellate(const std::vector<Ring>& rings, const Vec3d& normal) {
  Tessellation tess;
  for (const Ring& r : rings) tess.points.insert(tess.points.end(), r.begin(), r.end());
  TessPtr glu(gluNewTess(), gluDeleteTess);
  if (!glu) throw std::bad_alloc();
  using Callback = _GLUfuncptr;
  gluTessCallback(glu.get(), GLU_TESS_BEGIN_DATA, reinterpret_cast<Callback>(on_begin));
  gluTessCallback(glu.get(), GLU_TESS_EDGE_FLAG_DATA, reinterpret_cast<Callback>(on_edge_flag));
  gluTessCallback(glu.get(), GLU_TESS_VERTEX_DATA, reinterpret_cast<Callback>(on_vertex));
  gluTessCallback(glu.get(), GLU_TESS_COMBINE_DATA, reinterpret_cast<Callback>(on_combine));
  gluTessCallback(glu.get(), GLU_TESS_ERROR_DATA, reinterpret_cast<Callback>(on_error));
  gluTessCallback(glu.get(), GLU_TESS_END_DATA, reinterpret_cast<Callback>(on_end));
  gluTessProperty(glu.get(), GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
  gluTessNormal(glu.get(), normal.x, normal.y, normal.z);

  // GLU copies the coordinates at gluTessVertex, but keep them alive until the end regardless.
  std::vector<Point> coords = tess.points;
  gluTessBeginPolygon(glu.get(), &tess);
  size_t next = 0;
  for (const Ring& r : rings) {
    gluTessBeginContour(glu.get());
    for (size_t i = 0; i < r.size(); ++i, ++next) gluTessVertex(glu.get(), coords[next].data(), index_as_data(next));
    gluTessEndContour(glu.get());
  }
  gluTessEndPolygon(glu.get());
  return tess;
}

}  // namespace

MeshBuilder::MeshBuilder(const Taxonomy& taxonomy) : taxonomy_(taxonomy) {}

int MeshBuilder::add_entity(int level, int class_id, int parent, const std::string& source_id) {
  if (level < 1 || level > 3) throw std::logic_error(cat("MeshBuilder: entity level ", level));
  if (parent < -1 || parent >= static_cast<int>(mesh_.entities.size()))
    throw std::logic_error(cat("MeshBuilder: parent ", parent, " is not an earlier entity"));
  if (class_id < -1 || class_id >= static_cast<int>(taxonomy_.classes.size()))
    throw std::logic_error(cat("MeshBuilder: class id ", class_id));
  // Bad input, not a bug: a taxonomy (--taxonomy) can put a container on a finer level than what it holds.
  if (parent >= 0 && mesh_.entities[parent].level < level)
    throw Error(cat("object \"", source_id, "\" (level ", level, ") lies inside \"", mesh_.entities[parent].source_id,
                    "\" (level ", mesh_.entities[parent].level,
                    "); an object lies in one of the same or a coarser level (check the taxonomy's levels)"));
  mesh_.entities.push_back({level, class_id, parent, source_id});
  return static_cast<int>(mesh_.entities.size()) - 1;
}

std::array<int32_t, 3> MeshBuilder::level_classes(int face_class, const std::array<int32_t, 3>& chain) const {
  const auto class_of = [&](int32_t entity) { return entity < 0 ? -1 : mesh_.entities[entity].class_id; };
  std::array<int32_t, 3> c{};
  // Subpart: the opening, or the face itself where it is in no opening (subpart fallback).
  c[0] = chain[0] >= 0 ? class_of(chain[0]) : face_class;
  // Part: the enclosing surface (a window inherits its wall's class); a face outside any surface
  // keeps its own class if that is a part class, else it is a generic "surface".
  if (chain[1] >= 0)
    c[1] = class_of(chain[1]);
  else if (face_class >= 0 && taxonomy_.classes[face_class].level == 2)
    c[1] = face_class;
  else
    c[1] = taxonomy_.find("surface");
  c[2] = class_of(chain[2]);
  return c;
}

bool MeshBuilder::add_polygon(const std::vector<Ring>& rings, int face_class, int entity,
                              const std::string& polygon_id) {
  if (entity < -1 || entity >= static_cast<int>(mesh_.entities.size()))
    throw std::logic_error(cat("MeshBuilder: polygon entity ", entity));
  if (face_class < -1 || face_class >= static_cast<int>(taxonomy_.classes.size()))
    throw std::logic_error(cat("MeshBuilder: polygon class ", face_class));
  for (const Ring& r : rings)
    for (const Point& p : r)
      for (double x : p) {
        if (!std::isfinite(x)) throw Error(cat("polygon \"", polygon_id, "\": non-finite coordinate"));
        if (std::abs(x) > kMaxCoordinate)
          throw Error(cat("polygon \"", polygon_id, "\": coordinate ", x, " out of range"));
      }
  if (!polygon_id.empty() && !seen_polygon_ids_.insert(polygon_id).second) return false;

  // Local coordinates around the first point keep the tessellator's arithmetic precise.
  std::vector<Ring> local;
  Point ref{};
  for (const Ring& r : rings) {
    Ring c = cleaned(r);
    if (local.empty() && !c.empty()) ref = c[0];
    if (c.size() < 3) {
      if (local.empty()) break;  // no usable exterior ring
      continue;                  // a hole of fewer than 3 points cuts nothing
    }
    for (Point& p : c) p = {p[0] - ref[0], p[1] - ref[1], p[2] - ref[2]};
    local.push_back(std::move(c));
  }
  const Vec3d normal = local.empty() ? Vec3d{0, 0, 0} : newell_normal(local[0], Point{0, 0, 0});
  Tessellation tess;
  if (norm(normal) > 0) tess = tessellate(local, normal);
  if (tess.error != 0 || tess.triangles.empty()) {
    if (tess.error != 0)
      log_verbose(cat("polygon \"", polygon_id, "\": tessellation failed (", gluErrorString(tess.error), ")"));
    ++degenerate_;
    return true;
  }

  // Chain of entities: nearest level-1 and level-2 entity, outermost level-3 entity.
  std::array<int32_t, 3> chain{-1, -1, -1};
  for (int e = entity; e >= 0; e = mesh_.entities[e].parent) {
    const int level = mesh_.entities[e].level;
    if (level == 3 || chain[level - 1] < 0) chain[level - 1] = e;
  }
  const std::array<int32_t, 3> level_class = level_classes(face_class, chain);

  const auto base = static_cast<uint32_t>(vertices_abs_.size());
  for (const Point& p : tess.points) vertices_abs_.push_back({p[0] + ref[0], p[1] + ref[1], p[2] + ref[2]});
  const auto polygon_index = static_cast<int32_t>(mesh_.polygon_ids.size());
  mesh_.polygon_ids.push_back(polygon_id);
  for (const auto& t : tess.triangles) {
    mesh_.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    mesh_.tri_class.push_back(face_class);
    mesh_.tri_entity.push_back(chain);
    mesh_.tri_polygon.push_back(polygon_index);
    mesh_.tri_level_class.push_back(level_class);
  }
  return true;
}

SemanticMesh MeshBuilder::finish() {
  SemanticMesh mesh = std::move(mesh_);
  if (!vertices_abs_.empty()) {
    Point lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity()};
    for (const Point& p : vertices_abs_)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]);
    for (int k = 0; k < 3; ++k) mesh.origin[k] = std::floor(lo[k]);
  }
  mesh.vertices.reserve(vertices_abs_.size());
  for (const Point& p : vertices_abs_)
    mesh.vertices.push_back({p[0] - mesh.origin[0], p[1] - mesh.origin[1], p[2] - mesh.origin[2]});

  // Whole buildings: level-3 entities with no level-3 ancestor (a BuildingPart belongs to its Building).
  for (size_t e = 0; e < mesh.entities.size(); ++e) {
    if (mesh.entities[e].level != 3) continue;
    bool nested = false;
    for (int p = mesh.entities[e].parent; p >= 0 && !nested; p = mesh.entities[p].parent)
      nested = mesh.entities[p].level == 3;
    if (!nested) mesh.buildings.push_back(static_cast<int32_t>(e));
  }

  mesh_ = SemanticMesh{};
  vertices_abs_.clear();
  seen_polygon_ids_.clear();
  return mesh;
}

}  // namespace cls
