// citylangsplat raycast: per-view label maps, coverage and depth from the city model (paper 3.1).
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/city_mesh_inputs.h"
#include "cli/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "raycast/label_map_io.h"
#include "raycast/label_maps.h"
#include "raycast/raycaster.h"
#include "scene/scene.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

// OUT/<image name without extension>: the image stem for flat names, keeping sub-folders so two
// images "a/1.jpg" and "b/1.jpg" do not collide. cls::Error for names that would leave OUT.
std::vector<fs::path> view_dirs(const Scene& scene, const fs::path& out) {
  std::vector<fs::path> dirs;
  std::set<fs::path> seen;
  for (const auto& v : scene.views) {
    const fs::path rel = fs::path(v.name).lexically_normal().replace_extension();
    if (rel.empty() || rel.is_absolute() || *rel.begin() == "..")
      fail(scene.root, "image name '" + v.name + "' is not a relative path inside the scene");
    if (!seen.insert(rel).second) fail(scene.root, "two images map to the output folder '" + rel.string() + "'");
    dirs.push_back(out / rel);
  }
  return dirs;
}

}  // namespace

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
  const std::vector<fs::path> dirs = view_dirs(scene, out);
  const CityMeshInputs city = load_city_mesh_inputs(city_options, "raycast");
  const LabelTable labels(city.mesh);
  const Raycaster raycaster(city.vertices, city.mesh.triangles, opening_priority(city.mesh));
  log_info(cat("raycast: ", scene.views.size(), " views, ", city.mesh.num_triangles(), " triangles, ",
               city.mesh.buildings.size(), " buildings"));

  std::vector<RayHit> hits;
  LabelMaps maps;
  double coverage_sum = 0;
  Progress progress("raycast", scene.views.size(), "views");
  for (size_t k = 0; k < scene.views.size(); ++k) {
    const SceneView& view = scene.views[k];
    raycaster.cast_view(view.camera, view.pose, hits);
    labels.fill(hits, view.camera.width, view.camera.height, maps);
    write_label_maps(dirs[k], maps, city.taxonomy);
    size_t covered = 0;
    for (uint8_t c : maps.coverage) covered += c != 0;
    coverage_sum += static_cast<double>(covered) / maps.coverage.size();
    log_verbose(cat(view.name, ": coverage ", 100.0 * covered / maps.coverage.size(), "%"));
    progress.advance();
  }
  progress.finish();
  // Written last: its presence marks a finished run.
  write_text_atomic(out / "legend.json", city.taxonomy.legend_json());
  log_info(cat("raycast: wrote ", scene.views.size(), " views to ", out.string(), " (mean coverage ",
               100.0 * coverage_sum / scene.views.size(), "%)"));
  return 0;
}

}  // namespace cls
