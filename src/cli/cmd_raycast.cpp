// citylangsplat raycast: per-view label maps, coverage and depth from the city model (paper 3.1).
#include <filesystem>
#include <string>
#include <vector>

#include "core/args.h"
#include "cli/city_mesh_inputs.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/log.h"
#include "raycast/label_export.h"
#include "scene/scene.h"

namespace cls {
namespace fs = std::filesystem;

int cmd_raycast(int argc, char** argv) {
  Args args("raycast",
            "Raycast the city model into every view of a scene: one ray per pixel centre, all three "
            "levels from one cast. Writes OUT/<image>/level1.png, level2.png, level3.png (uint16, 0 = no "
            "label, k = class k-1 of OUT/legend.json), building.png (uint16 building index + 1), "
            "coverage.png (uint8 0/255), depth.pfm (z-depth, 0 where nothing is hit), preview.png.");
  args.option("scene", "", "scene directory (COLMAP or Pix4D; required)");
  add_city_mesh_options(args);
  args.option("resolution", "1", "divide the image size by 1, 2, 4 or 8 (as the training images)", "r")
      .option("out", "", "output directory (required)");
  if (!args.parse(argc, argv)) return 0;
  if (!args.has("scene")) throw UsageError("raycast: --scene is required (see --help)");
  if (!args.has("out")) throw UsageError("raycast: --out is required (see --help)");
  const int factor = args.get_int("resolution");
  if (factor != 1 && factor != 2 && factor != 4 && factor != 8)
    throw UsageError("raycast: --resolution must be 1, 2, 4 or 8");
  const CityMeshOptions city_options = city_mesh_options(args, "raycast");

  // Read and validate every input before the first file is written.
  SceneOptions scene_options;
  scene_options.resolution_factor = factor;
  const Scene scene = load_scene(args.get("scene"), scene_options);
  if (scene.views.empty()) fail(args.get("scene"), "the scene has no views");
  const fs::path out = args.get("out");
  label_map_dirs(scene, out);  // rejects image names that would leave OUT, before any file is written
  const SceneCityModel city = load_city_mesh_inputs(city_options, "raycast");
  const LabelExportSummary summary = export_label_maps(scene, city, out);
  log_info(cat("raycast: wrote ", summary.views, " views to ", out.string(), " (mean coverage ",
               100.0 * summary.mean_coverage, "%)"));
  return 0;
}

}  // namespace cls
