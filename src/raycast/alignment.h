#pragma once
// How well a scene's points lie on the city mesh (align-check), and the refinement of the city
// transform that makes them lie on it (align; docs/alignment.md).
#include <cstddef>
#include <vector>

#include "citymodel/scene_city_model.h"
#include "raycast/point_to_plane_icp.h"
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

// Distances of `points` moved by `motion` to the mesh, divided by `scene_scale` (the transform's scale of
// model metres into the scene frame; 1 where the mesh is in model metres).
std::vector<double> distances_after(const ClosestPointQuery& mesh, std::vector<Vec3d> points,
                                    const CityTransform& motion, double scene_scale);

// Distance of every sparse point of `scene` to the nearest triangle of the city mesh, in
// city-model units (scene distances divided by the transform's scale); the scene must have points.
AlignmentStats check_alignment(const Scene& scene, const SceneCityModel& city, double threshold);

// The scene points `align` fits to the mesh: the sparse points. cls::Error naming the scene if it has none.
std::vector<Vec3d> sparse_points(const Scene& scene);

struct AlignmentRefinement {
  CityTransform refined;           // city CRS -> scene frame, the given transform corrected
  AlignmentStats before, after;    // point-to-mesh distances in city-model units, at `threshold`
  // The same distances at the finest ICP gate: whether points come to lie on the surfaces, which the
  // coarse threshold cannot tell for errors below it (0.25 m moves few points across 0.5 m).
  AlignmentStats fine_before, fine_after;
  IcpResult icp;                   // its gates in scene units
};

// Refines city.transform so that `points` (scene frame) lie on the city mesh. `options` gates are in
// city-model units (metres); `threshold` as in check_alignment.
AlignmentRefinement refine_alignment(const std::vector<Vec3d>& points, const SceneCityModel& city,
                                     const IcpOptions& options, double threshold);

// How far transform `a` places the city model from transform `b`, in city-model units.
struct TransformDifference {
  double centre = 0;            // displacement of the mesh's bounding-box centre
  double max_displacement = 0;  // largest displacement of a mesh vertex
  double rotation_deg = 0;      // angle of the rotation between them
  double scale = 0;             // scale of a relative to b, minus 1
};
TransformDifference transform_difference(const CityTransform& a, const CityTransform& b, const SemanticMesh& mesh);

}  // namespace cls
