#include "raycast/closest_point.h"

#include <cmath>

#include "raycast/embree_scene.h"

namespace cls {

Vec3d closest_point_on_triangle(Vec3d p, Vec3d a, Vec3d b, Vec3d c, bool* on_face) {
  if (on_face) *on_face = false;
  // Voronoi regions of the vertices, then of the edges, else the face.
  const Vec3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3d bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  // On an edge: p projects onto the closed face only when exactly on that edge (determinant 0).
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    if (on_face) *on_face = vc == 0;
    return a + (d1 / (d1 - d3)) * ab;
  }
  const Vec3d cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    if (on_face) *on_face = vb == 0;
    return a + (d2 / (d2 - d6)) * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    if (on_face) *on_face = va == 0;
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double denom = va + vb + vc;
  if (!(std::abs(denom) > 0)) {  // degenerate triangle: its closest edge point
    Vec3d best = a;
    for (const auto& [s, e] : {std::pair{a, b}, std::pair{b, c}, std::pair{a, c}}) {
      const Vec3d d = e - s;
      const double len2 = dot(d, d);
      const double t = len2 > 0 ? std::fmin(1.0, std::fmax(0.0, dot(p - s, d) / len2)) : 0.0;
      const Vec3d q = s + t * d;
      if (dot(q - p, q - p) < dot(best - p, best - p)) best = q;
    }
    return best;
  }
  const double v = vb / denom, w = vc / denom;
  if (on_face) *on_face = true;
  return a + v * ab + w * ac;
}

struct ClosestPointQuery::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<Vec3f> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

struct Nearest {
  const std::vector<Vec3f>* vertices;
  const std::vector<std::array<uint32_t, 3>>* triangles;
  Vec3d p;
  double best2 = INFINITY;  // squared distance
  Vec3d best;
  uint32_t triangle = 0;
  bool on_face = false;
};

// Embree calls this for every triangle whose bounds reach the query sphere; shrinking the radius
// to the best distance so far prunes the rest of the BVH.
bool visit_triangle(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<Nearest*>(args->userPtr);
  const auto& t = (*q->triangles)[args->primID];
  const auto& v = *q->vertices;
  bool on_face = false;
  const Vec3d c =
      closest_point_on_triangle(q->p, cast<double>(v[t[0]]), cast<double>(v[t[1]]), cast<double>(v[t[2]]), &on_face);
  const double d2 = dot(c - q->p, c - q->p);
  // A tie (the same point reached through a neighbour's edge) keeps the face, not the edge.
  if (d2 > q->best2 || (d2 == q->best2 && (q->on_face || !on_face))) return false;
  q->best2 = d2;
  q->best = c;
  q->triangle = args->primID;
  q->on_face = on_face;
  // Embree culls in float around a float copy of p: widen the radius by more than both roundings
  // so the true nearest triangle is never pruned.
  const double d = std::sqrt(d2);
  const double slack = 1e-6 * (d + std::fmax(std::fabs(q->p.x), std::fmax(std::fabs(q->p.y), std::fabs(q->p.z))));
  args->query->radius = static_cast<float>(d + slack);
  return true;
}

}  // namespace

ClosestPointQuery::ClosestPointQuery(const std::vector<Vec3f>& vertices,
                                     const std::vector<std::array<uint32_t, 3>>& triangles)
    : impl_(std::make_unique<Impl>()) {
  validate_triangle_mesh(vertices, triangles, "closest-point query");
  impl_->vertices = vertices;
  impl_->triangles = triangles;
  impl_->device = new_embree_device();
  impl_->scene = build_triangle_scene(impl_->device, vertices, triangles);
}

ClosestPointQuery::~ClosestPointQuery() = default;

MeshPoint ClosestPointQuery::nearest(Vec3d p) const {
  Nearest q{&impl_->vertices, &impl_->triangles, p, INFINITY, {}, 0, false};
  RTCPointQuery query{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), 0.0f, INFINITY};
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(impl_->scene, &query, &context, visit_triangle, &q);
  MeshPoint out;
  out.distance = std::sqrt(q.best2);
  if (!std::isfinite(out.distance)) return out;
  out.point = q.best;
  out.triangle = q.triangle;
  out.on_face = q.on_face;
  const auto& t = impl_->triangles[q.triangle];
  const auto& v = impl_->vertices;
  const Vec3d a = cast<double>(v[t[0]]);
  const Vec3d n = cross(cast<double>(v[t[1]]) - a, cast<double>(v[t[2]]) - a);
  const double len = norm(n);
  if (len > 0) out.normal = (1 / len) * n;
  return out;
}

std::vector<double> ClosestPointQuery::distances(const std::vector<Vec3d>& points) const {
  std::vector<double> out(points.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (int64_t i = 0; i < static_cast<int64_t>(points.size()); ++i) out[i] = distance(points[i]);
  return out;
}

}  // namespace cls
