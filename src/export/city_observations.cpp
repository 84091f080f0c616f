#include "export/city_observations.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "raycast/label_export.h"
#include "raycast/label_map_io.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

// A point on the mesh: where it lies, the area it stands for and the finest object of its triangle.
struct SurfacePoint {
  Vec3d position;
  double area = 0;
  int32_t object = -1;
};

std::vector<SurfacePoint> surface_points(const SemanticMesh& mesh, const std::vector<Vec3f>& v,
                                         const ObservationSettings& settings) {
  const std::vector<int32_t> finest = finest_object_of_triangles(mesh);
  std::vector<double> areas(mesh.triangles.size());
  double total = 0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3d a = cast<double>(v[tri[0]]), b = cast<double>(v[tri[1]]), c = cast<double>(v[tri[2]]);
    areas[t] = 0.5 * norm(cross(b - a, c - a));
    total += areas[t];
  }
  const double density = total > 0 ? static_cast<double>(settings.sample_points) / total : 0.0;
  std::mt19937 random(settings.seed);
  const auto unit = [&] { return (random() >> 8) * (1.0 / 16777216.0); };  // [0, 1), the same on every platform
  std::vector<SurfacePoint> points;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (finest[t] < 0 || !(areas[t] > 0)) continue;
    const auto& tri = mesh.triangles[t];
    const Vec3d a = cast<double>(v[tri[0]]), b = cast<double>(v[tri[1]]), c = cast<double>(v[tri[2]]);
    const int64_t k = std::max<int64_t>(1, std::llround(areas[t] * density));
    for (int64_t i = 0; i < k; ++i) {
      double r1 = unit(), r2 = unit();
      if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;  // uniform on the triangle
      points.push_back({a + r1 * (b - a) + r2 * (c - a), areas[t] / static_cast<double>(k), finest[t]});
    }
  }
  return points;
}

}  // namespace

std::vector<ObjectObservation> observe_city_objects(const CityObjects& objects, const SemanticMesh& mesh,
                                                    const std::vector<Vec3f>& scene_vertices, const Scene& scene,
                                                    const fs::path& labels_dir, const std::vector<int32_t>& gaussian_object,
                                                    const ObservationSettings& settings) {
  const size_t num_objects = objects.objects.size();
  if (num_objects != mesh.entities.size())
    throw Error(cat("city objects: ", num_objects, " objects for a mesh of ", mesh.entities.size(), " entities"));
  std::vector<ObjectObservation> out(num_objects);
  // Adds to an object and everything it lies in.
  const auto for_chain = [&](int32_t object, const auto& add) {
    for (int32_t o = object; o >= 0; o = objects.objects[o].parent) add(out[o]);
  };
  for (const int32_t g : gaussian_object)
    if (g >= 0 && static_cast<size_t>(g) < num_objects) for_chain(g, [](ObjectObservation& o) { ++o.gaussians; });

  const std::vector<SurfacePoint> points = surface_points(mesh, scene_vertices, settings);
  std::vector<char> seen(points.size(), 0);
  const std::vector<fs::path> dirs = label_map_dirs(scene, labels_dir);
  Progress progress("observations", scene.views.size(), "views");
  std::vector<int64_t> pixels(num_objects);
  for (size_t k = 0; k < scene.views.size(); ++k) {
    const SceneView& view = scene.views[k];
    const int W = view.camera.width, H = view.camera.height;
    const auto [object, depth] = read_view_hits(dirs[k], W, H);
    std::fill(pixels.begin(), pixels.end(), 0);
    for (const int32_t o : object)
      if (o >= 0 && static_cast<size_t>(o) < num_objects) ++pixels[o];
    std::vector<char> shown(num_objects, 0);
    for (size_t o = 0; o < num_objects; ++o)
      if (pixels[o] > 0)
        for (int32_t p = static_cast<int32_t>(o); p >= 0; p = objects.objects[p].parent) {
          out[p].pixels += pixels[o];
          shown[p] = 1;
        }
    for (size_t o = 0; o < num_objects; ++o) out[o].views += shown[o];

    const Mat3d& R = view.pose.R;
    const PinholeCamera& c = view.camera;
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < static_cast<int64_t>(points.size()); ++i) {
      if (seen[i]) continue;
      const Vec3d q = R * points[i].position + view.pose.t;
      if (!(q.z > 0)) continue;
      const double u = std::floor(c.fx * q.x / q.z + c.cx), v = std::floor(c.fy * q.y / q.z + c.cy);
      if (!(u >= 0 && u < W && v >= 0 && v < H)) continue;
      const size_t p = static_cast<size_t>(v) * W + static_cast<size_t>(u);
      const double d = depth.data[p];
      if (d > 0 && std::abs(q.z - d) <= settings.relative_depth_tolerance * d && object[p] == points[i].object) seen[i] = 1;
    }
    progress.advance();
  }
  progress.finish();
  for (size_t i = 0; i < points.size(); ++i)
    for_chain(points[i].object, [&](ObjectObservation& o) {
      o.area += points[i].area;
      if (seen[i]) o.seen_area += points[i].area;
    });
  return out;
}

}  // namespace cls
