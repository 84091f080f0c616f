#pragma once
// `citylangsplat tile`: the district's buildings and views measured (footprints from the city model,
// which view sees which building from one raycast per view), partitioned (tile_plan.h), and written as
// one scene directory per tile that `run` takes as it is:
//   TILES/tiles.json
//   TILES/<tile>/scene.json        city_model, city_transform, taxonomy, lod (absolute) and "tile"
//   TILES/<tile>/images/<name>     symbolic links to the district's images
//   TILES/<tile>/sparse/0/*.bin    the district's COLMAP model: the tile's images and the points they see
// Every tile raycasts the whole city model, so neighbours seen in its images are labelled too and every
// tile numbers the city objects alike.
#include <filesystem>

#include "citymodel/scene_city_model.h"
#include "scene/colmap.h"
#include "scene/scene.h"
#include "tiles/tile_plan.h"

namespace cls {

struct TileOptions {
  int max_images = 30;       // images per tile before it is split
  double min_share = 0.2;    // a view joins a tile where the tile's buildings are this share of its building pixels
  int raycast_downscale = 4; // the visibility raycast runs at 1/4 of the image size
};

std::vector<BuildingFootprint> building_footprints(const SceneCityModel& city);
// Each view's pixels per building (indices as building_footprints), from a raycast at 1/downscale.
BuildingPixels building_pixels(const Scene& scene, const SceneCityModel& city, int downscale);

// The plan for a loaded district (paths as given: made absolute here).
TilePlan make_tile_plan(const Scene& scene, const SceneCityModel& city, const TileOptions& options,
                        const std::string& city_path, const std::string& transform_path,
                        const std::string& taxonomy_path, int lod);

// The district's COLMAP model cut to a tile's images (and their cameras) and the sparse points they see,
// wherever those lie (VastGaussian's coverage-based point selection: a tile starts with the geometry of
// everything its images show, not only of its own buildings, so what its views see beyond its cell is not
// made up by floaters inside it). Tracks and 2D observations point only at what is kept.
ColmapModel tile_colmap(const ColmapModel& district, const std::vector<std::string>& images);

// The scene's COLMAP model folder; cls::Error for a scene without one (Pix4D: `citylangsplat scene convert`).
std::string require_colmap_model(const std::filesystem::path& scene_dir);

// Writes every tile's directory and then tiles.json (last: a folder with tiles.json is complete);
// run-tiles' finished tasks of an earlier plan no longer count (their markers hold its fingerprint).
void write_tiles(const TilePlan& plan, const std::filesystem::path& tiles_dir);

}  // namespace cls
