// citylangsplat tile: cut a district into tiles of whole buildings (src/tiles/tile_scene.h).
#include <cstdio>
#include <filesystem>

#include "citymodel/city_model.h"
#include "cli/commands.h"
#include "core/args.h"
#include "core/error.h"
#include "pipeline/pipeline_config.h"
#include "scene/scene.h"
#include "tiles/tile_scene.h"

namespace cls {
namespace fs = std::filesystem;

int cmd_tile(int argc, char** argv) {
  Args args("tile",
            "Cut a district into tiles for run-tiles (docs/scale.md): the city model's buildings are split by "
            "recursive bisection of their footprints until each tile's images fit --max-images; an image joins "
            "every tile whose buildings cover at least --min-share of its building pixels (one raycast per "
            "image) and the tile whose cell its camera stands in; a tile keeps the sparse points its images see. "
            "Writes TILES/<tile>/ (scene.json, images linked, the COLMAP model cut to the tile) and TILES/tiles.json. The city model comes from --config FILE or SCENE_DIR/scene.json unless given.");
  PipelineConfig c;  // only its city-model fields, read as `run` reads them
  std::filesystem::path config_file, out;
  TileOptions o;
  bool overwrite = false;
  args.bind("scene", c.scene_dir, "the district's scene directory (COLMAP model)").required()
      .bind("config", config_file, "JSON scene config: city_model, city_transform, taxonomy, lod (paths relative to it)")
      .default_text("SCENE_DIR/scene.json where it exists");
  pipeline_options().declare(args, c, is_scene_config_option);
  args.bind("out", out, "tiles directory to write").required()
      .bind("max-images", o.max_images, "images per tile before it is split")
      .bind("min-share", o.min_share, "share of an image's building pixels that makes it join a tile")
      .flag("overwrite", overwrite, "plan again over an existing tiles directory (run-tiles then reruns every task; "
                                    "the stages whose inputs did not change are reused)");
  if (!args.parse(argc, argv)) return 0;
  pipeline_options().apply(args, c, is_scene_config_option);
  apply_scene_config(args, config_file, c);
  const fs::path scene_dir = c.scene_dir;
  if (c.city.empty()) throw UsageError("tile: no city model: give --city, or a scene.json with \"city_model\"");
  if (o.max_images < 1) throw UsageError("tile: --max-images must be >= 1");
  if (!(o.min_share > 0 && o.min_share <= 1)) throw UsageError("tile: --min-share must be in (0, 1]");
  if (fs::exists(out / "tiles.json") && !overwrite)
    throw UsageError("tile: " + (out / "tiles.json").string() + " exists: give --overwrite to plan again");

  require_colmap_model(scene_dir);  // before the raycast: the tiles are written as COLMAP models
  const Scene scene = load_scene(scene_dir.string());
  const SceneCityModel city = load_scene_city_model(c.city, c.city_transform, c.city_options, "tile");
  const TilePlan plan = make_tile_plan(scene, city, o, c.city, c.city_transform, c.city_options.taxonomy_path,
                                       c.city_options.lod);
  write_tiles(plan, out);
  size_t images = 0;
  for (const Tile& t : plan.tiles) images += t.images.size();
  std::printf("%zu tiles of %zu buildings; %zu images, %zu tile images (%.2f tiles per image): %s\n", plan.tiles.size(),
              city.mesh.buildings.size(), scene.views.size(), images,
              static_cast<double>(images) / static_cast<double>(scene.views.size()), (out / "tiles.json").string().c_str());
  return 0;
}

}  // namespace cls
