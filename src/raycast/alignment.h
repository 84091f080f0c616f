#pragma once
// How well a scene's sparse points lie on the city mesh (the align-check command).
#include <cstddef>
#include <vector>

#include "citymodel/scene_city_model.h"
#include "scene/scene.h"

namespace cls {

struct AlignmentStats {
  size_t points = 0;
  double threshold = 0;        // metres (city-model units for check_alignment)
  double fraction_within = 0;  // share of points with distance <= threshold
  double median = 0, mean = 0;
};

// Below this share of points near the mesh the model and the scene are probably misaligned:
// a correct alignment of an urban scene puts most facade and roof points on the mesh, while
// vegetation, cars and unmodelled ground rarely make up three quarters of the points.
constexpr double kMisalignedFraction = 0.25;

// Statistics of point-to-mesh distances; `distances` must not be empty.
AlignmentStats alignment_stats(std::vector<double> distances, double threshold);

// Distance of every sparse point of `scene` to the nearest triangle of the city mesh, in
// city-model units (scene distances divided by the transform's scale); the scene must have points.
AlignmentStats check_alignment(const Scene& scene, const SceneCityModel& city, double threshold);

}  // namespace cls
