#include "synth/synth_geometry.h"

#include <algorithm>
#include <cmath>

#include "synth/clutter.h"
#include "synth/random.h"

namespace cls::synth {

uint32_t SynthGeometry::add_vertex(Vec3d p) {
  vertices.push_back(cast<float>(p));
  return static_cast<uint32_t>(vertices.size() - 1);
}

void SynthGeometry::add_triangle(uint32_t a, uint32_t b, uint32_t c, TriangleOrigin origin, uint8_t prio) {
  triangles.push_back({a, b, c});
  origins.push_back(origin);
  priority.push_back(prio);
}

Vec3f SynthGeometry::triangle_normal(uint32_t tri) const {
  const auto& t = triangles[tri];
  const Vec3f n = cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]);
  const float len = norm(n);
  return len > 0 ? (1.0f / len) * n : Vec3f{0, 0, 1};
}

double SynthGeometry::triangle_area(uint32_t tri) const {
  const auto& t = triangles[tri];
  const Vec3d a = cast<double>(vertices[t[0]]), b = cast<double>(vertices[t[1]]), c = cast<double>(vertices[t[2]]);
  return 0.5 * norm(cross(b - a, c - a));
}

SynthGeometry build_synth_geometry(const SemanticMesh& mesh, const Taxonomy& taxonomy, uint64_t seed, int occluders) {
  SynthGeometry g;
  for (const auto& v : mesh.vertices) {
    g.add_vertex({v[0], v[1], v[2]});
    g.city_bounds.extend({v[0], v[1], v[2]});
  }
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int cls = mesh.tri_class[t];
    const bool known = cls >= 0 && cls < static_cast<int>(taxonomy.classes.size());
    const Material m = known ? material_for_class(taxonomy.classes[cls]) : Material::PlainSurface;
    const uint8_t opening = known && taxonomy.classes[cls].level == 1 ? 1 : 0;
    const auto& tri = mesh.triangles[t];
    g.add_triangle(tri[0], tri[1], tri[2], {SurfaceSource::City, static_cast<uint32_t>(t), m}, opening);
  }

  const Box3d& city = g.city_bounds;
  const Vec3d size = city.size();
  const double radius = std::max(0.5 * std::hypot(size.x, size.y), 3.0);
  g.terrain_z = city.lo.z - kTerrainGap;
  g.terrain_half_extent = std::max(150.0, 20 * radius);
  const Vec3d c = city.center();

  Rng rng(seed, Stream::Clutter, 1);
  g.brick_walls = rng.uniform() < 0.4;
  // A road passes the building on one side, a few metres from its footprint.
  g.road.axis = rng.below(2);
  const double side = rng.uniform() < 0.5 ? -1 : 1;
  const int axis = g.road.axis;
  g.road.half_width = 3.0;
  g.road.offset = c[axis] + side * (0.5 * size[axis] + 4.0 + g.road.half_width + rng.uniform(0, 2));

  const double spread = std::max(8.0, 0.7 * radius);
  g.clutter_area.extend({city.lo.x - spread, city.lo.y - spread, g.terrain_z});
  g.clutter_area.extend({city.hi.x + spread, city.hi.y + spread, city.hi.z});

  const double e = g.terrain_half_extent;
  const uint32_t q0 = g.add_vertex({c.x - e, c.y - e, g.terrain_z}), q1 = g.add_vertex({c.x + e, c.y - e, g.terrain_z});
  const uint32_t q2 = g.add_vertex({c.x + e, c.y + e, g.terrain_z}), q3 = g.add_vertex({c.x - e, c.y + e, g.terrain_z});
  g.add_triangle(q0, q1, q2, {SurfaceSource::Terrain, 0, Material::Terrain});
  g.add_triangle(q0, q2, q3, {SurfaceSource::Terrain, 0, Material::Terrain});

  g.clutter = place_clutter(city, g.clutter_area, g.road, g.terrain_z, seed);
  place_occluders(city, g.road, g.terrain_z, seed, occluders, g.clutter);
  for (uint32_t i = 0; i < g.clutter.size(); ++i) add_clutter_mesh(g, i);
  return g;
}

}  // namespace cls::synth
