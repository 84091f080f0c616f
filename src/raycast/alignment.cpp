#include "raycast/alignment.h"

#include <algorithm>
#include <numeric>

#include "core/error.h"
#include "raycast/closest_point.h"

namespace cls {

AlignmentStats alignment_stats(std::vector<double> distances, double threshold) {
  if (distances.empty()) throw Error("alignment statistics of no points");
  AlignmentStats s;
  s.points = distances.size();
  s.threshold = threshold;
  const size_t within = std::count_if(distances.begin(), distances.end(), [&](double d) { return d <= threshold; });
  s.fraction_within = static_cast<double>(within) / s.points;
  s.mean = std::accumulate(distances.begin(), distances.end(), 0.0) / s.points;
  // Median: the middle element, or the mean of the two middle ones.
  const size_t mid = s.points / 2;
  std::nth_element(distances.begin(), distances.begin() + mid, distances.end());
  s.median = distances[mid];
  if (s.points % 2 == 0) s.median = 0.5 * (s.median + *std::max_element(distances.begin(), distances.begin() + mid));
  return s;
}

std::vector<double> distances_after(const ClosestPointQuery& mesh, std::vector<Vec3d> points,
                                    const CityTransform& motion, double scene_scale) {
  for (auto& p : points) p = motion.apply(p);
  std::vector<double> distances = mesh.distances(points);
  for (double& d : distances) d /= scene_scale;
  return distances;
}

AlignmentStats check_alignment(const Scene& scene, const SceneCityModel& city, double threshold) {
  const ClosestPointQuery mesh(city.vertices, city.mesh.triangles);
  return alignment_stats(distances_after(mesh, sparse_points(scene), CityTransform::identity(), city.transform.scale()),
                         threshold);
}

std::vector<Vec3d> sparse_points(const Scene& scene) {
  if (scene.points.empty()) fail(scene.root, "the scene has no sparse points to compare with the city model");
  std::vector<Vec3d> points;
  points.reserve(scene.points.size());
  for (const auto& p : scene.points) points.push_back(p.xyz);
  return points;
}

AlignmentRefinement refine_alignment(const std::vector<Vec3d>& points, const SceneCityModel& city,
                                     const IcpOptions& options, double threshold) {
  const double scale = city.transform.scale();
  IcpOptions scene_units = options;
  scene_units.capture *= scale;
  scene_units.finest *= scale;
  // The mesh stays where the given transform puts it; ICP moves the points onto it, and the inverse of
  // that motion corrects the transform: x_scene = motion^-1 * M * x_city.
  const ClosestPointQuery mesh(city.vertices, city.mesh.triangles);
  AlignmentRefinement r;
  const std::vector<double> before = distances_after(mesh, points, CityTransform::identity(), scale);
  r.before = alignment_stats(before, threshold);
  r.fine_before = alignment_stats(before, options.finest);
  r.icp = point_to_plane_icp(mesh, points, scene_units);
  const std::vector<double> after = distances_after(mesh, points, r.icp.motion, scale);
  r.after = alignment_stats(after, threshold);
  r.fine_after = alignment_stats(after, options.finest);
  r.refined = inverse(r.icp.motion) * city.transform;
  return r;
}

TransformDifference transform_difference(const CityTransform& a, const CityTransform& b, const SemanticMesh& mesh) {
  if (mesh.vertices.empty()) throw Error("transform difference over an empty mesh");
  TransformDifference d;
  const double unit = b.scale();
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi = -1.0 * lo;
  for (const auto& v : mesh.vertices) {
    const Vec3d x{v[0] + mesh.origin[0], v[1] + mesh.origin[1], v[2] + mesh.origin[2]};
    d.max_displacement = std::max(d.max_displacement, norm(a.apply(x) - b.apply(x)) / unit);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], x[k]);
      hi[k] = std::max(hi[k], x[k]);
    }
  }
  const Vec3d centre = 0.5 * (lo + hi);
  d.centre = norm(a.apply(centre) - b.apply(centre)) / unit;
  d.rotation_deg = rotation_angle(a.rotation() * transpose(b.rotation())) * 180 / M_PI;
  d.scale = a.scale() / unit - 1;
  return d;
}

}  // namespace cls
