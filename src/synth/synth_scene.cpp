#include "synth/synth_scene.h"

#include <algorithm>
#include <filesystem>

#include "citymodel/city_objects.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_file.h"
#include "core/log.h"
#include "core/progress.h"
#include "core/run_layout.h"
#include "synth/sparse_points.h"

namespace cls::synth {

namespace fs = std::filesystem;

std::string settings_problem(const SynthSettings& s) {
  if (s.views < 2 || s.views > 10000) return cat("--views must be in [2, 10000], got ", s.views);
  if (s.width < 16 || s.width > 8192 || s.height < 16 || s.height > 8192)
    return cat("--width and --height must be in [16, 8192], got ", s.width, "x", s.height);
  if (!(s.hfov_deg >= 10 && s.hfov_deg <= 150)) return cat("horizontal field of view must be in [10, 150] degrees");
  if (s.samples_per_view < 1) return "sparse samples per view must be positive";
  if (!(s.point_noise >= 0 && s.point_noise < 1)) return "point noise must be in [0, 1)";
  if (!(s.gt_density > 0 && s.gt_density <= 1e5)) return "--gt-density must be in (0, 100000] points per square unit";
  if (s.occluders < 0 || s.occluders > 100) return cat("--occluders must be in [0, 100], got ", s.occluders);
  return "";
}

namespace {
// The box of each building's triangles (mesh.buildings order; buildings without triangles left out).
std::vector<Box3d> building_bounds(const SemanticMesh& mesh) {
  std::vector<Box3d> boxes(mesh.buildings.size());
  const std::vector<int32_t> building = building_of_triangles(mesh);
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    if (building[t] >= 0)
      for (uint32_t v : mesh.triangles[t]) boxes[building[t]].extend({mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]});
  boxes.erase(std::remove_if(boxes.begin(), boxes.end(), [](const Box3d& b) { return b.empty(); }), boxes.end());
  if (boxes.empty()) fail(mesh.source_path, "--per-building: the city model has no building with surfaces at this LoD");
  return boxes;
}
}  // namespace

SynthScene render_synth_scene(const SemanticMesh& mesh, const Taxonomy& taxonomy, const SynthSettings& settings) {
  SynthScene scene;
  scene.geometry = build_synth_geometry(mesh, taxonomy, settings.seed, settings.occluders);
  const CameraRigOptions rig{settings.views, settings.width, settings.height, settings.hfov_deg, settings.seed};
  scene.views = settings.per_building ? make_building_views(building_bounds(mesh), rig)
                                      : make_uav_views(scene.geometry.city_bounds, rig);
  const SurfaceShader shader(scene.geometry, mesh, settings.seed);
  const ViewRenderer renderer(scene.geometry, mesh, shader);
  {
    Progress progress("synth: render", scene.views.size(), "views");
    for (const SynthView& view : scene.views) {
      scene.rendered.push_back(renderer.render(view));
      progress.advance();
    }
  }
  scene.colmap = make_colmap_model(scene.views, scene.rendered,
                                   {settings.samples_per_view, settings.point_noise, 2, settings.seed});
  scene.gt_points = sample_gt_points(scene.geometry, mesh, shader,
                                     {settings.gt_density, settings.gt_density / 8, settings.seed});
  log_info(cat("synth: ", scene.views.size(), " views, ", scene.colmap.points.size(), " sparse points, ",
               scene.gt_points.size(), " ground-truth points"));
  return scene;
}

void write_synth_outputs(const std::string& dir, const SynthScene& scene, const Taxonomy& taxonomy) {
  const fs::path root(dir);
  Progress progress("synth: write", scene.views.size(), "views");
  for (size_t v = 0; v < scene.views.size(); ++v) {
    const fs::path name(scene.views[v].name);
    write_image(root / "images" / name, scene.rendered[v].image);
    write_image(SceneFiles{root}.gt_labels() / (name.stem().string() + ".png"), scene.rendered[v].labels);
    progress.advance();
  }
  progress.finish();
  const std::string sparse = (root / "sparse" / "0").string();
  fs::create_directories(sparse);
  write_colmap_binary(sparse, scene.colmap);
  write_colmap_text(sparse, scene.colmap);
  write_text_atomic(SceneFiles{root}.gt_legend(), taxonomy.legend_json());
  write_gt_ply(SceneFiles{root}.gt_points().string(), scene.gt_points);
}

}  // namespace cls::synth
