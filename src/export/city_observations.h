#pragma once
// What a run saw of each city object (issue 35 §2, the enriched city model): in how many views and
// pixels the label maps show it, how much of its surface some view's first hit sees, and how many of the
// model's Gaussians belong to it. An object includes what lies in it: a wall counts its windows' pixels,
// area and Gaussians, a building everything of it.
//
// Covered area: points spread over every triangle (by area, a fixed seed) are projected into each view;
// one is seen where it lies in the image, in front of the camera, at the label map's depth (within
// `relative_depth_tolerance`) and on the object the label map names there (the triangle's own finest
// object). The fraction is seen area / area over the object's triangles.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "citymodel/city_objects.h"
#include "citymodel/semantic_mesh.h"
#include "core/math.h"
#include "scene/scene.h"

namespace cls {

struct ObjectObservation {
  int64_t views = 0;      // views whose label maps show at least one pixel of it
  int64_t pixels = 0;     // its pixels over all views
  double area = 0;        // its surface area (scene units squared)
  double seen_area = 0;   // the part of it that some view sees
  int64_t gaussians = 0;  // Gaussians whose provenance object is it or lies in it
  double covered_fraction() const { return area > 0 ? seen_area / area : 0.0; }
};

struct ObservationSettings {
  int64_t sample_points = 200000;  // points spread over the mesh for the covered area (at least one per triangle)
  double relative_depth_tolerance = 0.02;
  uint32_t seed = 1;
};

// `mesh` must be the one the label maps were raycast from (objects = city_objects(mesh), entity order),
// `scene_vertices` its vertices in the scene frame, `scene` the views at the label maps' size.
// `gaussian_object` (n, -1 none) is the language model's provenance. cls::Error naming the file for a
// missing or mis-sized label map.
std::vector<ObjectObservation> observe_city_objects(const CityObjects& objects, const SemanticMesh& mesh,
                                                    const std::vector<Vec3f>& scene_vertices, const Scene& scene,
                                                    const std::filesystem::path& labels_dir,
                                                    const std::vector<int32_t>& gaussian_object,
                                                    const ObservationSettings& settings = {});

}  // namespace cls
