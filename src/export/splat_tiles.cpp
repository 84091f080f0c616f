#include "export/splat_tiles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cls {

std::array<double, 12> bounding_box(const std::vector<Vec3d>& points, const std::vector<double>& radii,
                                    const std::vector<int64_t>& subset) {
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const int64_t i : subset)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], points[i][a] - radii[i]);
      hi[a] = std::max(hi[a], points[i][a] + radii[i]);
    }
  std::array<double, 12> box{};
  for (int a = 0; a < 3; ++a) {
    box[a] = (lo[a] + hi[a]) / 2;
    box[3 + 4 * a] = (hi[a] - lo[a]) / 2;  // half-axis a along axis a
  }
  return box;
}

namespace {

// A tile being built: the Gaussians of its whole subtree and its quadtree cell on the ground.
struct Pending {
  int tile;
  std::vector<int64_t> subtree;
  double x0, x1, y0, y1;
};

}  // namespace

SplatTileTree build_splat_tiles(const std::vector<Vec3d>& centres, const std::vector<double>& radii,
                                const std::vector<double>& importance, int64_t max_splats) {
  const size_t n = centres.size();
  if (radii.size() != n || importance.size() != n) throw std::invalid_argument("build_splat_tiles: inputs of different lengths");
  if (n == 0 || max_splats < 1) throw std::invalid_argument("build_splat_tiles: no Gaussian, or max_splats < 1");
  SplatTileTree tree;
  std::vector<int64_t> all(n);
  for (size_t i = 0; i < n; ++i) all[i] = static_cast<int64_t>(i);
  // The root cell spans the 1st to 99th percentile of the centres: a few far floaters (a trained sky,
  // stray Gaussians) would make every cell kilometres wide; outside it they join the border cells.
  const auto span = [&](int axis) {
    std::vector<double> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = centres[i][axis];
    const size_t lo = (n - 1) / 100, hi = n - 1 - (n - 1) / 100;
    std::nth_element(v.begin(), v.begin() + lo, v.end());
    const double a = v[lo];
    std::nth_element(v.begin(), v.begin() + hi, v.end());
    return std::array<double, 2>{a, v[hi]};
  };
  const auto [x0, x1] = span(0);
  const auto [y0, y1] = span(1);
  tree.tiles.push_back({"r", {}, {}, 0, {}});
  // Breadth first (a parent before its children), without recursion: a tile's depth can reach n / max_splats.
  std::vector<Pending> queue{{0, std::move(all), x0, x1, y0, y1}};
  for (size_t q = 0; q < queue.size(); ++q) {
    Pending p = std::move(queue[q]);
    SplatTile& tile = tree.tiles[p.tile];
    tile.box = bounding_box(centres, radii, p.subtree);
    if (static_cast<int64_t>(p.subtree.size()) <= max_splats) {
      tile.splats = std::move(p.subtree);
      std::sort(tile.splats.begin(), tile.splats.end());
      continue;
    }
    // The max_splats most important first (a total order: ties by index); the rest need no order.
    std::nth_element(p.subtree.begin(), p.subtree.begin() + max_splats, p.subtree.end(), [&](int64_t a, int64_t b) {
      return importance[a] > importance[b] || (importance[a] == importance[b] && a < b);
    });
    tile.splats.assign(p.subtree.begin(), p.subtree.begin() + max_splats);
    std::sort(tile.splats.begin(), tile.splats.end());
    const double area = std::max((p.x1 - p.x0) * (p.y1 - p.y0), 1e-12);
    tile.geometric_error = std::sqrt(area / static_cast<double>(max_splats));
    const double mx = (p.x0 + p.x1) / 2, my = (p.y0 + p.y1) / 2;
    std::array<std::vector<int64_t>, 4> quadrant;
    for (auto it = p.subtree.begin() + max_splats; it != p.subtree.end(); ++it)
      quadrant[(centres[*it].x >= mx ? 1 : 0) + (centres[*it].y >= my ? 2 : 0)].push_back(*it);
    const std::string name = tile.name;  // `tile` dangles once tiles grows
    for (int k = 0; k < 4; ++k) {
      if (quadrant[k].empty()) continue;
      const int child = static_cast<int>(tree.tiles.size());
      tree.tiles[p.tile].children.push_back(child);
      tree.tiles.push_back({name + std::to_string(k), {}, {}, 0, {}});
      queue.push_back({child, std::move(quadrant[k]), k & 1 ? mx : p.x0, k & 1 ? p.x1 : mx, k & 2 ? my : p.y0, k & 2 ? p.y1 : my});
    }
  }
  // Never below a descendant's error (3D Tiles: a child's error is at most its parent's); children
  // come after their parent, so backwards is bottom-up.
  for (size_t t = tree.tiles.size(); t-- > 0;)
    for (const int c : tree.tiles[t].children)
      tree.tiles[t].geometric_error = std::max(tree.tiles[t].geometric_error, tree.tiles[c].geometric_error);
  return tree;
}

}  // namespace cls
