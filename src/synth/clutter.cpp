#include "synth/clutter.h"

#include <algorithm>
#include <cmath>

#include "synth/random.h"

namespace cls::synth {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Local frame of an object: x along its heading, y to its left, z up.
struct Frame {
  Vec3d origin, x, y, z{0, 0, 1};
  Frame(Vec3d o, double heading) : origin(o), x{std::cos(heading), std::sin(heading), 0}, y{-std::sin(heading), std::cos(heading), 0} {}
  Vec3d at(double a, double b, double c) const { return origin + a * x + b * y + c * z; }
};

class ShapeWriter {
 public:
  ShapeWriter(SynthGeometry& g, uint32_t object) : g_(g), object_(object) {}

  // Box with its centre at local (cx, cy, cz) and half sizes (hx, hy, hz).
  void box(const Frame& f, Vec3d c, Vec3d h, Material m) {
    uint32_t v[8];
    for (int i = 0; i < 8; ++i)
      v[i] = g_.add_vertex(f.at(c.x + ((i & 1) ? h.x : -h.x), c.y + ((i & 2) ? h.y : -h.y), c.z + ((i & 4) ? h.z : -h.z)));
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) quad(v[q[0]], v[q[1]], v[q[2]], v[q[3]], m);
  }

  // Closed frustum from a (radius ra) to b (radius rb; 0 gives a cone) with `segments` sides.
  void frustum(Vec3d a, Vec3d b, double ra, double rb, int segments, Material m) {
    const Vec3d axis = normalized(b - a);
    const Vec3d helper = std::abs(axis.z) < 0.9 ? Vec3d{0, 0, 1} : Vec3d{1, 0, 0};
    const Vec3d u = normalized(cross(axis, helper)), w = cross(axis, u);
    const uint32_t ca = g_.add_vertex(a), cb = g_.add_vertex(b);
    std::vector<uint32_t> ring_a, ring_b;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * kPi * s / segments;
      const Vec3d dir = std::cos(phi) * u + std::sin(phi) * w;
      ring_a.push_back(g_.add_vertex(a + ra * dir));
      if (rb > 0) ring_b.push_back(g_.add_vertex(b + rb * dir));
    }
    for (int s = 0; s < segments; ++s) {
      const int n = (s + 1) % segments;
      tri(ca, ring_a[n], ring_a[s], m);
      if (rb > 0) {
        quad(ring_a[s], ring_a[n], ring_b[n], ring_b[s], m);
        tri(cb, ring_b[s], ring_b[n], m);
      } else {
        tri(ring_a[s], ring_a[n], cb, m);
      }
    }
  }

  // Icosahedron subdivided once (80 faces), scaled by (rx, ry, rz): a rounded tree canopy.
  void blob(Vec3d c, double rx, double ry, double rz, Material m) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    std::vector<Vec3d> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    const int faces[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                              {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                              {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    const auto place = [&](Vec3d q) {
      q = normalized(q);
      return g_.add_vertex(c + Vec3d{rx * q.x, ry * q.y, rz * q.z});
    };
    for (const auto& f : faces) {
      const Vec3d a = p[f[0]], b = p[f[1]], d = p[f[2]];
      const Vec3d ab = 0.5 * (a + b), bd = 0.5 * (b + d), da = 0.5 * (d + a);
      const uint32_t va = place(a), vb = place(b), vd = place(d), vab = place(ab), vbd = place(bd), vda = place(da);
      tri(va, vab, vda, m);
      tri(vab, vb, vbd, m);
      tri(vda, vbd, vd, m);
      tri(vab, vbd, vda, m);
    }
  }

 private:
  void tri(uint32_t a, uint32_t b, uint32_t c, Material m) { g_.add_triangle(a, b, c, {SurfaceSource::Clutter, object_, m}); }
  void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d, Material m) {
    tri(a, b, c, m);
    tri(a, c, d, m);
  }
  SynthGeometry& g_;
  uint32_t object_;
};

double footprint_radius(ClutterKind kind) {
  switch (kind) {
    case ClutterKind::Tree: return 2.2;
    case ClutterKind::Conifer: return 1.6;
    case ClutterKind::Car: return 2.4;
    case ClutterKind::Bench: return 1.1;
    case ClutterKind::Fence: return 3.2;
  }
  return 1;
}

// Whether o's footprint circle overlaps one of the objects already placed.
bool overlaps(const std::vector<ClutterObject>& placed, const ClutterObject& o) {
  return std::any_of(placed.begin(), placed.end(), [&](const ClutterObject& q) {
    const double dx = q.base.x - o.base.x, dy = q.base.y - o.base.y;
    return std::sqrt(dx * dx + dy * dy) < q.radius + o.radius;
  });
}

bool on_road(const Road& road, Vec3d p, double radius) {
  return std::abs(p[road.axis] - road.offset) < road.half_width + radius;
}
}  // namespace

std::vector<ClutterObject> place_clutter(const Box3d& city, const Box3d& area, const Road& road, double terrain_z,
                                         uint64_t seed) {
  Rng rng(seed, Stream::Clutter);
  std::vector<ClutterKind> kinds = {ClutterKind::Car, ClutterKind::Car, ClutterKind::Bench, ClutterKind::Fence};
  const int trees = 3 + rng.below(3);
  for (int i = 0; i < trees; ++i) kinds.push_back(rng.uniform() < 0.6 ? ClutterKind::Tree : ClutterKind::Conifer);

  constexpr double kMargin = 1.0;  // free space around the building footprint
  std::vector<ClutterObject> placed;
  for (const ClutterKind kind : kinds) {
    const double radius = footprint_radius(kind);
    for (int attempt = 0; attempt < 200; ++attempt) {
      ClutterObject o;
      o.kind = kind;
      o.radius = radius;
      o.color_key = static_cast<uint32_t>(rng.next());
      if (kind == ClutterKind::Car) {
        // Parked along the road, in one of its two lanes.
        const int along = 1 - road.axis;
        o.base[road.axis] = road.offset + (rng.uniform() < 0.5 ? -1.5 : 1.5);
        o.base[along] = rng.uniform(area.lo[along] + radius, area.hi[along] - radius);
        o.heading = (along == 0 ? 0.0 : 0.5 * kPi) + (rng.uniform() < 0.5 ? 0.0 : kPi);
      } else {
        o.base.x = rng.uniform(area.lo.x + radius, area.hi.x - radius);
        o.base.y = rng.uniform(area.lo.y + radius, area.hi.y - radius);
        o.heading = rng.uniform(0, 2 * kPi);
        if (on_road(road, o.base, radius)) continue;
      }
      o.base.z = terrain_z;
      const bool hits_building = o.base.x > city.lo.x - kMargin - radius && o.base.x < city.hi.x + kMargin + radius &&
                                 o.base.y > city.lo.y - kMargin - radius && o.base.y < city.hi.y + kMargin + radius;
      if (hits_building) continue;
      if (overlaps(placed, o)) continue;
      placed.push_back(o);
      break;
    }
  }
  return placed;
}

void place_occluders(const Box3d& city, const Road& road, double terrain_z, uint64_t seed, int count,
                     std::vector<ClutterObject>& placed) {
  Rng rng(seed, Stream::Occluders);
  for (int i = 0; i < count; ++i) {
    ClutterObject o;
    o.kind = rng.uniform() < 0.6 ? ClutterKind::Tree : ClutterKind::Conifer;
    o.radius = footprint_radius(o.kind);
    for (int attempt = 0; attempt < 200; ++attempt) {
      // A side of the footprint box (axis, low or high end), a point along it, a distance beyond it.
      const int axis = rng.below(2), along = 1 - axis;
      const bool high = rng.uniform() < 0.5;
      const double gap = o.radius + rng.uniform(0.1, 2.5);
      o.base[axis] = high ? city.hi[axis] + gap : city.lo[axis] - gap;
      o.base[along] = rng.uniform(city.lo[along], city.hi[along]);
      o.base.z = terrain_z;
      o.heading = rng.uniform(0, 2 * kPi);
      o.color_key = static_cast<uint32_t>(rng.next());
      if (on_road(road, o.base, o.radius)) continue;
      if (overlaps(placed, o)) continue;
      placed.push_back(o);
      break;
    }
  }
}

void add_clutter_mesh(SynthGeometry& g, uint32_t index) {
  const ClutterObject& o = g.clutter[index];
  ShapeWriter w(g, index);
  const Frame f(o.base, o.heading);
  const double s = 0.85 + 0.3 * unit_from_bits(mix64(o.color_key));  // size variation
  switch (o.kind) {
    case ClutterKind::Tree: {
      const double trunk = 1.8 * s;
      w.frustum(f.at(0, 0, 0), f.at(0, 0, trunk + 0.5), 0.2 * s, 0.14 * s, 8, Material::Bark);
      w.blob(f.at(0, 0, trunk + 1.3 * s), 1.9 * s, 1.7 * s, 1.6 * s, Material::Foliage);
      break;
    }
    case ClutterKind::Conifer:
      w.frustum(f.at(0, 0, 0), f.at(0, 0, 1.0), 0.15 * s, 0.12 * s, 8, Material::Bark);
      w.frustum(f.at(0, 0, 0.8), f.at(0, 0, 5.5 * s), 1.5 * s, 0, 12, Material::Foliage);
      break;
    case ClutterKind::Car: {
      w.box(f, {0, 0, 0.65}, {2.1, 0.88, 0.33}, Material::CarPaint);
      w.box(f, {-0.25, 0, 1.22}, {1.15, 0.78, 0.24}, Material::CarWindow);
      for (int i = 0; i < 4; ++i) {
        const double x = (i & 1) ? 1.35 : -1.35, y = (i & 2) ? 0.8 : -0.8;
        w.frustum(f.at(x, y - 0.11, 0.32), f.at(x, y + 0.11, 0.32), 0.32, 0.32, 10, Material::Tyre);
      }
      break;
    }
    case ClutterKind::Bench:
      w.box(f, {0, 0, 0.45}, {0.9, 0.22, 0.03}, Material::Wood);
      w.box(f, {0, 0.2, 0.75}, {0.9, 0.03, 0.18}, Material::Wood);
      for (int i = 0; i < 4; ++i) w.box(f, {(i & 1) ? 0.8 : -0.8, (i & 2) ? 0.18 : -0.18, 0.21}, {0.03, 0.03, 0.21}, Material::Wood);
      break;
    case ClutterKind::Fence: {
      const int posts = 6;
      for (int i = 0; i < posts; ++i)
        w.box(f, {-3.0 + 6.0 * i / (posts - 1), 0, 0.5}, {0.05, 0.05, 0.5}, Material::Wood);
      w.box(f, {0, 0, 0.35}, {3.0, 0.025, 0.06}, Material::Wood);
      w.box(f, {0, 0, 0.8}, {3.0, 0.025, 0.06}, Material::Wood);
      break;
    }
  }
}

}  // namespace cls::synth
