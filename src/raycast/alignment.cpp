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

AlignmentStats check_alignment(const Scene& scene, const SceneCityModel& city, double threshold) {
  std::vector<Vec3d> points;
  points.reserve(scene.points.size());
  for (const auto& p : scene.points) points.push_back(p.xyz);
  std::vector<double> distances = ClosestPointQuery(city.vertices, city.mesh.triangles).distances(points);
  // Scene units -> city-model units: the transform scales model metres into the scene frame.
  const double scale = city.transform.scale();
  for (double& d : distances) d /= scale;
  return alignment_stats(std::move(distances), threshold);
}

}  // namespace cls
