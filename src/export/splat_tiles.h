#pragma once
// Gaussians cut into a 3D Tiles hierarchy with levels of detail (export --format 3dtiles): a quadtree
// over the ground plane (a district is wide and flat), additive refinement. Each tile holds at most
// `max_splats` Gaussians: an inner tile keeps the most important ones of its area (opacity times
// footprint: what a distant viewer sees first) and hands the rest to its four quadrants, so a client
// far away draws the coarse tiles only and one close by adds the finer ones; every Gaussian lies in
// exactly one tile. A tile's geometric error is what leaving out its descendants costs: the spacing of
// its own Gaussians over its area (sqrt(area / count)), never below a descendant's; leaves have 0.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace cls {

struct SplatTile {
  std::string name;                // "r", then a digit per quadrant level: "r0", "r03" ...
  std::vector<int64_t> splats;     // indices into the input, in ascending order
  std::array<double, 12> box{};    // 3D Tiles box around its own and its descendants' 3-sigma extents
  double geometric_error = 0;      // metres; 0 for a leaf
  std::vector<int> children;       // indices into SplatTileTree::tiles
};

struct SplatTileTree {
  std::vector<SplatTile> tiles;    // tiles[0] is the root; a parent before its children
};

// 3D Tiles' box (centre, then three half-axis vectors) around `points[i]` for i in `subset`, each
// grown by its radius; axis-aligned.
std::array<double, 12> bounding_box(const std::vector<Vec3d>& points, const std::vector<double>& radii,
                                    const std::vector<int64_t>& subset);

// `centres` in the tileset's local frame (metres, z up), `radii` their 3-sigma extents, `importance`
// the order in which a coarse tile keeps them (higher first; ties by index). std::invalid_argument for
// different lengths, no splat or max_splats < 1.
SplatTileTree build_splat_tiles(const std::vector<Vec3d>& centres, const std::vector<double>& radii,
                                const std::vector<double>& importance, int64_t max_splats);

}  // namespace cls
