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
  std::string scene_dir;
  fs::path out;
  SceneOptions scene_options;
  CityMeshOptions city_options;
  args.bind("scene", scene_dir, "scene directory (COLMAP, OPF or Pix4D)").required();
  city_options.bind(args)
      .bind("resolution", scene_options.resolution_factor,
            "divide the image size by 1, 2, 4 or 8 (as the training images)")
      .short_name("r")
      .bind("out", out, "output directory")
      .required();
  if (!args.parse(argc, argv)) return 0;
  const int factor = scene_options.resolution_factor;
  if (factor != 1 && factor != 2 && factor != 4 && factor != 8)
    throw UsageError("raycast: --resolution must be 1, 2, 4 or 8");

  // Read and validate every input before the first file is written.
  const Scene scene = load_scene(scene_dir, scene_options);
  if (scene.views.empty()) fail(scene_dir, "the scene has no views");
  label_map_dirs(scene, out);  // rejects image names that would leave OUT, before any file is written
  const SceneCityModel city = load_city_mesh_inputs(city_options, "raycast");
  const LabelExportSummary summary = export_label_maps(scene, city, out);
  log_info(cat("raycast: wrote ", summary.views, " views to ", out.string(), " (mean coverage ",
               100.0 * summary.mean_coverage, "%)"));
  return 0;
}

}  // namespace cls
