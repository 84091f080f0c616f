#include "synth/gt_point_cloud.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/atomic_file.h"
#include "synth/random.h"

namespace cls::synth {

namespace {
std::array<uint8_t, 3> to_rgb8(Vec3f c) {
  const auto q = [](float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return {q(c.x), q(c.y), q(c.z)};
}
}  // namespace

std::vector<GtPoint> sample_gt_points(const SynthGeometry& g, const SemanticMesh& mesh, const SurfaceShader& shader,
                                      const GtCloudOptions& options) {
  const auto n_tri = static_cast<int64_t>(g.triangles.size());
  std::vector<std::vector<GtPoint>> per_triangle(g.triangles.size());
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t t = 0; t < n_tri; ++t) {
    const TriangleOrigin& o = g.origins[t];
    if (o.source == SurfaceSource::Terrain) continue;
    const bool city = o.source == SurfaceSource::City;
    Rng rng(options.seed, Stream::GroundTruth, static_cast<uint64_t>(t));
    const double expected = (city ? options.city_density : options.context_density) * g.triangle_area(t);
    const auto count = static_cast<int64_t>(std::floor(expected + rng.uniform()));
    const auto& tri = g.triangles[t];
    const Vec3f n = g.triangle_normal(t);
    const int32_t label = city ? mesh.tri_level_class[o.index][0] : -1;
    for (int64_t k = 0; k < count; ++k) {
      // Uniform on the triangle: sqrt-warped barycentrics.
      const float r1 = static_cast<float>(std::sqrt(rng.uniform())), r2 = static_cast<float>(rng.uniform());
      const Vec3f p = (1 - r1) * g.vertices[tri[0]] + (r1 * (1 - r2)) * g.vertices[tri[1]] + (r1 * r2) * g.vertices[tri[2]];
      per_triangle[t].push_back({p, to_rgb8(shader.albedo(static_cast<uint32_t>(t), p, n)), label});
    }
  }

  std::vector<GtPoint> points;
  for (int64_t t = 0; t < n_tri; ++t)
    if (g.origins[t].source == SurfaceSource::City) points.insert(points.end(), per_triangle[t].begin(), per_triangle[t].end());

  // Terrain: uniform in the clutter area, at the context density, outside the building footprint.
  const Box3d& a = g.clutter_area;
  const Box3d& b = g.city_bounds;
  uint32_t terrain_tri = 0;
  while (g.origins[terrain_tri].source != SurfaceSource::Terrain) ++terrain_tri;
  Rng rng(options.seed, Stream::GroundTruth, g.triangles.size());
  const double area = (a.hi.x - a.lo.x) * (a.hi.y - a.lo.y);
  const auto count = static_cast<int64_t>(std::floor(options.context_density * area + rng.uniform()));
  for (int64_t k = 0; k < count; ++k) {
    const Vec3f p = cast<float>(Vec3d{rng.uniform(a.lo.x, a.hi.x), rng.uniform(a.lo.y, a.hi.y), g.terrain_z});
    if (p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y) continue;
    points.push_back({p, to_rgb8(shader.albedo(terrain_tri, p, Vec3f{0, 0, 1})), -1});
  }

  for (int64_t t = 0; t < n_tri; ++t)
    if (g.origins[t].source == SurfaceSource::Clutter)
      points.insert(points.end(), per_triangle[t].begin(), per_triangle[t].end());
  return points;
}

void write_gt_ply(const std::string& path, const std::vector<GtPoint>& points) {
  static_assert(sizeof(float) == 4 && sizeof(int32_t) == 4, "PLY float and int are 4 bytes");
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment CityLangSplat synthetic ground truth; class: taxonomy class id, "
      "-1 = not city model\nelement vertex " +
      std::to_string(points.size()) +
      "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nproperty int class\nend_header\n";
  constexpr size_t kRecord = 3 * 4 + 3 + 4;
  std::string body(points.size() * kRecord, '\0');
  // Little-endian by memcpy: the build targets are little-endian (x86-64, aarch64).
  for (size_t i = 0; i < points.size(); ++i) {
    char* r = body.data() + i * kRecord;
    const GtPoint& p = points[i];
    const float xyz[3] = {p.position.x, p.position.y, p.position.z};
    std::memcpy(r, xyz, 12);
    std::memcpy(r + 12, p.rgb.data(), 3);
    std::memcpy(r + 15, &p.label, 4);
  }
  write_text_atomic(path, header + body);
}

}  // namespace cls::synth
