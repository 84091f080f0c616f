#include "raycast/label_export.h"

#include <set>

#include "citymodel/city_objects.h"
#include "citymodel/mesh_ply.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "raycast/label_map_io.h"
#include "raycast/label_maps.h"
#include "raycast/raycaster.h"

namespace cls {
namespace fs = std::filesystem;

std::vector<fs::path> label_map_dirs(const Scene& scene, const fs::path& out) {
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

LabelExportSummary export_label_maps(const Scene& scene, const SceneCityModel& city, const fs::path& out) {
  const std::vector<fs::path> dirs = label_map_dirs(scene, out);
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
  write_city_objects(out / "objects.json", city_objects(city.mesh, city.taxonomy));
  write_mesh_ply((out / "city_mesh.ply").string(), city.mesh, city.taxonomy, &city.transform);
  write_city_transform((out / kLabelsCityTransform).string(), city.transform, city.mesh.crs);
  write_text_atomic(out / "legend.json", city.taxonomy.legend_json());
  LabelExportSummary summary;
  summary.views = scene.views.size();
  summary.mean_coverage = scene.views.empty() ? 0 : coverage_sum / scene.views.size();
  return summary;
}

}  // namespace cls
