#pragma once
// Ground-truth labelled point cloud of a synthetic scene, like the ZAHA facade dataset: points on
// the city model's surfaces with their class, and points on terrain and clutter with class -1.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "synth/shading.h"
#include "synth/synth_geometry.h"

namespace cls::synth {

struct GtPoint {
  Vec3f position;
  std::array<uint8_t, 3> rgb;
  int32_t label;  // level-1 class id of the taxonomy (as in the label images, minus 1); -1 = not city model
};

struct GtCloudOptions {
  double city_density = 400;    // samples per square metre (scene unit) on the city model
  double context_density = 50;  // on clutter and on the terrain inside the clutter area
  uint64_t seed = 1;
};

// Area-uniform samples: each triangle gets floor(density * area + u) points (u uniform in [0, 1)),
// uniformly distributed over it; the terrain is sampled only inside g.clutter_area and outside the
// building's footprint box. Colour: the material albedo (unlit). Order: city triangles, terrain,
// clutter, each in triangle order; independent of the thread count.
std::vector<GtPoint> sample_gt_points(const SynthGeometry& g, const SemanticMesh& mesh, const SurfaceShader& shader,
                                      const GtCloudOptions& options);

// Binary little-endian PLY: float x y z, uchar red green blue, int class. Written atomically.
void write_gt_ply(const std::string& path, const std::vector<GtPoint>& points);

}  // namespace cls::synth
