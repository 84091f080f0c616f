#include "synth/opening_frames.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace cls::synth {

namespace {
float distance_to_segment(Vec3f p, Vec3f a, Vec3f b) {
  const Vec3f ab = b - a;
  const float len2 = dot(ab, ab);
  const float t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return norm(p - (a + t * ab));
}

// Vertex identity by position (millimetre grid): openings may be made of several polygons whose
// shared edges use different vertex indices.
using PositionKey = std::array<int64_t, 3>;
PositionKey position_key(Vec3f p) {
  return {std::llround(p.x * 1000.0), std::llround(p.y * 1000.0), std::llround(p.z * 1000.0)};
}
}  // namespace

float OpeningFrame::distance_to_border(Vec3f p) const {
  float best = std::numeric_limits<float>::infinity();
  for (const auto& s : border) best = std::min(best, distance_to_segment(p, s[0], s[1]));
  return best;
}

OpeningFrames build_opening_frames(const SynthGeometry& g, const SemanticMesh& mesh) {
  OpeningFrames out;
  out.frame_of_triangle.assign(g.triangles.size(), -1);
  // Group key: entity index, or -(polygon + 1) for faces without an opening entity.
  std::map<int64_t, std::vector<uint32_t>> groups;
  for (uint32_t t = 0; t < g.triangles.size(); ++t) {
    const TriangleOrigin& o = g.origins[t];
    if (o.source != SurfaceSource::City || (o.material != Material::Glass && o.material != Material::Door)) continue;
    const int entity = mesh.tri_entity[o.index][0];
    groups[entity >= 0 ? entity : -static_cast<int64_t>(mesh.tri_polygon[o.index]) - 1].push_back(t);
  }
  for (const auto& [key, tris] : groups) {
    OpeningFrame f;
    Vec3f normal{0, 0, 0};
    std::map<std::pair<PositionKey, PositionKey>, int> edge_count;
    std::map<PositionKey, Vec3f> position;
    for (const uint32_t t : tris) {
      const auto& tri = g.triangles[t];
      // Area-weighted normal, with every face turned to the same side as the first.
      Vec3f n = cross(g.vertices[tri[1]] - g.vertices[tri[0]], g.vertices[tri[2]] - g.vertices[tri[0]]);
      if (dot(n, normal) < 0) n = -n;
      normal = normal + n;
      for (int e = 0; e < 3; ++e) {
        PositionKey a = position_key(g.vertices[tri[e]]), b = position_key(g.vertices[tri[(e + 1) % 3]]);
        position[a] = g.vertices[tri[e]];
        position[b] = g.vertices[tri[(e + 1) % 3]];
        if (b < a) std::swap(a, b);
        ++edge_count[{a, b}];
      }
    }
    const float len = norm(normal);
    const Vec3f n = len > 0 ? (1.0f / len) * normal : Vec3f{1, 0, 0};
    const Vec3f horizontal = cross(Vec3f{0, 0, 1}, n);
    f.axis_u = norm(horizontal) > 1e-3f ? normalized(horizontal) : Vec3f{1, 0, 0};
    f.axis_v = normalized(cross(n, f.axis_u));
    f.u_min = f.v_min = std::numeric_limits<float>::infinity();
    f.u_max = f.v_max = -std::numeric_limits<float>::infinity();
    for (const auto& [k, p] : position) {
      f.u_min = std::min(f.u_min, dot(p, f.axis_u));
      f.u_max = std::max(f.u_max, dot(p, f.axis_u));
      f.v_min = std::min(f.v_min, dot(p, f.axis_v));
      f.v_max = std::max(f.v_max, dot(p, f.axis_v));
    }
    for (const auto& [edge, count] : edge_count)
      if (count == 1) f.border.push_back({position[edge.first], position[edge.second]});
    for (const uint32_t t : tris) out.frame_of_triangle[t] = static_cast<int32_t>(out.frames.size());
    out.frames.push_back(std::move(f));
  }
  return out;
}

}  // namespace cls::synth
