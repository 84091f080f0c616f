#pragma once
// How a district is cut into tiles (docs/scale.md): whole buildings per tile, split by recursive
// bisection of the buildings' footprint centres until each tile's images fit a budget. The cells of
// the bisection partition the ground plane, so every point belongs to exactly one tile: that is what
// `merge` keeps of each tile, and why no Gaussian is kept twice at a seam.
#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace cls {

// A half-open rectangle of the ground plane (scene x, y); unbounded sides are infinite.
struct TileCell {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  double x0 = -kInf, y0 = -kInf, x1 = kInf, y1 = kInf;
  bool contains(double x, double y) const { return x0 <= x && x < x1 && y0 <= y && y < y1; }
};

struct BuildingFootprint {
  std::string id;                     // the city model's building id
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // footprint box in the scene frame
  double cx() const { return 0.5 * (x0 + x1); }
  double cy() const { return 0.5 * (y0 + y1); }
};

// Which buildings a view sees: the pixels of each building whose first hit it is (sparse: a view of a
// city sees a few of its buildings), and their sum; and where the view stands.
struct ViewBuildings {
  std::vector<std::pair<int32_t, int64_t>> pixels;  // (building, pixels), pixels > 0
  int64_t total = 0;
  // The camera centre on the ground plane (scene x, y); NaN where unknown (in no cell).
  double camera_x = std::numeric_limits<double>::quiet_NaN(), camera_y = std::numeric_limits<double>::quiet_NaN();
};
using BuildingPixels = std::vector<ViewBuildings>;  // one per view

// The views of a set of buildings (`in_set[b]` non-zero): those where the set covers at least
// `min_share` of the pixels the view has on any building (and at least one pixel).
std::vector<int> views_of_buildings(const std::vector<char>& in_set, const BuildingPixels& pixels, double min_share);

// The views of a tile: those of its buildings, and every view whose camera stands in its cell. A camera
// in the cell sees the tile's Gaussians nearest to it, whatever it looks at: a tile that never trained
// from it leaves floaters there that fill that view of the merged model (VastGaussian's camera selection
// has the same reason).
std::vector<int> views_of_tile(const std::vector<char>& in_set, const TileCell& cell, const BuildingPixels& pixels,
                               double min_share);

struct PlannedTile {
  std::vector<int> buildings;  // indices into the footprints
  TileCell cell;
  std::vector<int> views;      // indices into the views, ascending
};

// Recursive bisection: a set of buildings whose views (views_of_tile) exceed `max_images` is split at the median of
// its footprint centres along the wider axis; a single building (or several with one centre) is never
// split: its tile may then hold more than max_images views (the caller says so). Buildings that no view
// sees at `min_share` on their own take no part (`unseen`): every tile has views, and the cells still
// cover the whole plane. Tiles come out in depth-first order.
struct Partition {
  std::vector<PlannedTile> tiles;
  std::vector<int> unseen;
};
Partition partition_buildings(const std::vector<BuildingFootprint>& footprints, const BuildingPixels& pixels,
                              int max_images, double min_share);

// tiles.json: the plan as written by `tile` and read by run-tiles, tiles status and merge.
struct Tile {
  std::string name;                    // tile_000, ...: also its directory under the tiles folder
  std::vector<std::string> buildings;  // building ids
  TileCell cell;                       // the part of the plane this tile owns in the merged model
  std::vector<std::string> images;     // image names as in the scene's model
};

struct TilePlan {
  std::filesystem::path scene;  // the district's scene directory (absolute)
  std::string city_model, city_transform, taxonomy;  // absolute paths ("" = none / built-in)
  int lod = 0;
  int max_images = 30;
  double min_share = 0;
  std::vector<Tile> tiles;
  std::vector<std::string> unseen;  // buildings no view sees: in no tile (the cells still cover them)
};

void write_tile_plan(const std::filesystem::path& file, const TilePlan& plan);  // atomic
// cls::Error naming the file for malformed JSON or fields.
TilePlan read_tile_plan(const std::filesystem::path& file);
// TILES/tiles.json; cls::Error saying to run `citylangsplat tile` when it is missing.
TilePlan read_tiles_dir(const std::filesystem::path& tiles_dir);

}  // namespace cls
