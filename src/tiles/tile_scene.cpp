#include "tiles/tile_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "citymodel/city_objects.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "core/run_layout.h"
#include "raycast/label_maps.h"
#include "raycast/raycaster.h"
#include "scene/colmap.h"

namespace cls {
namespace fs = std::filesystem;

std::vector<BuildingFootprint> building_footprints(const SceneCityModel& city) {
  const SemanticMesh& mesh = city.mesh;
  std::vector<BuildingFootprint> out(mesh.buildings.size());
  for (size_t b = 0; b < mesh.buildings.size(); ++b)
    out[b] = {mesh.entities[mesh.buildings[b]].source_id, TileCell::kInf, TileCell::kInf, -TileCell::kInf, -TileCell::kInf};
  const std::vector<int32_t> building = building_of_triangles(mesh);  // as the label maps' building.png
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (building[t] < 0) continue;
    BuildingFootprint& f = out[building[t]];
    for (uint32_t v : mesh.triangles[t]) {
      const Vec3f p = city.vertices[v];
      f.x0 = std::min(f.x0, double(p.x)), f.y0 = std::min(f.y0, double(p.y));
      f.x1 = std::max(f.x1, double(p.x)), f.y1 = std::max(f.y1, double(p.y));
    }
  }
  return out;
}

BuildingPixels building_pixels(const Scene& scene, const SceneCityModel& city, int downscale) {
  const LabelTable labels(city.mesh);
  const Raycaster raycaster(city.vertices, city.mesh.triangles, opening_priority(city.mesh));
  BuildingPixels pixels(scene.views.size());
  Progress progress("tile: visibility", scene.views.size(), "views");
  std::vector<RayHit> hits;
  LabelMaps maps;
  std::vector<int64_t> count(city.mesh.buildings.size() + 1, 0);
  for (size_t v = 0; v < scene.views.size(); ++v) {
    PinholeCamera cam = scene.views[v].camera;
    const double s = 1.0 / downscale;
    cam.fx *= s, cam.fy *= s, cam.cx *= s, cam.cy *= s;
    cam.width = std::max(1, cam.width / downscale), cam.height = std::max(1, cam.height / downscale);
    raycaster.cast_view(cam, scene.views[v].pose, hits);
    labels.fill(hits, cam.width, cam.height, maps);
    std::fill(count.begin(), count.end(), 0);
    for (uint16_t b : maps.building) ++count[b];  // b = building + 1, 0 = none
    for (size_t b = 1; b < count.size(); ++b)
      if (count[b] > 0) {
        pixels[v].pixels.push_back({static_cast<int32_t>(b - 1), count[b]});
        pixels[v].total += count[b];
      }
    const Vec3d centre = scene.views[v].pose.center();
    pixels[v].camera_x = centre.x, pixels[v].camera_y = centre.y;
    progress.advance();
  }
  return pixels;
}

TilePlan make_tile_plan(const Scene& scene, const SceneCityModel& city, const TileOptions& o,
                        const std::string& city_path, const std::string& transform_path,
                        const std::string& taxonomy_path, int lod) {
  const std::vector<BuildingFootprint> footprints = building_footprints(city);
  if (footprints.empty()) fail(city_path, "the city model has no buildings to tile");
  const BuildingPixels pixels = building_pixels(scene, city, o.raycast_downscale);
  // A building without surfaces at this LoD is never hit, so it is among the unseen.
  const Partition partition = partition_buildings(footprints, pixels, o.max_images, o.min_share);
  if (partition.tiles.empty())
    fail(city_path, "no image sees any building of the city model: check the city transform (`align-check`)");

  auto absolute = [](const std::string& p) { return p.empty() ? p : fs::absolute(p).lexically_normal().string(); };
  TilePlan plan;
  plan.scene = fs::absolute(scene.root).lexically_normal();
  plan.city_model = absolute(city_path);
  plan.city_transform = absolute(transform_path);
  plan.taxonomy = absolute(taxonomy_path);
  plan.lod = lod;
  plan.max_images = o.max_images;
  plan.min_share = o.min_share;
  for (int b : partition.unseen) plan.unseen.push_back(footprints[b].id);
  if (!plan.unseen.empty())
    log_info(cat("tile: ", plan.unseen.size(), " of ", footprints.size(), " buildings are seen by no image (at --min-share ",
                 o.min_share, " on their own): in no tile"));
  for (size_t i = 0; i < partition.tiles.size(); ++i) {
    const PlannedTile& p = partition.tiles[i];
    Tile t;
    char name[32];
    std::snprintf(name, sizeof name, "tile_%03zu", i);
    t.name = name;
    t.cell = p.cell;
    for (int b : p.buildings) t.buildings.push_back(footprints[b].id);
    for (int v : p.views) t.images.push_back(scene.views[v].name);
    if (static_cast<int>(t.images.size()) > o.max_images)
      log_warn(cat("tile: ", t.name, " has ", t.images.size(), " images (> --max-images ", o.max_images,
                   "): it cannot be split further (one building, or centres that coincide); its images include the "
                   "cameras standing in its cell"));
    plan.tiles.push_back(std::move(t));
  }
  return plan;
}

std::string require_colmap_model(const fs::path& scene_dir) {
  const std::string model_dir = find_colmap_model(scene_dir.string());
  if (model_dir.empty())
    fail(scene_dir.string(), "tile needs a COLMAP model (sparse/0): convert a Pix4D scene with `citylangsplat scene "
                             "convert` first");
  return model_dir;
}

ColmapModel tile_colmap(const ColmapModel& all, const std::vector<std::string>& images) {
  const std::set<std::string> names(images.begin(), images.end());
  ColmapModel m;
  for (const auto& [id, image] : all.images)
    if (names.count(image.name)) {
      m.images[id] = image;
      m.cameras[image.camera_id] = all.cameras.at(image.camera_id);
    }
  // The points the kept images observe, found from their 2D points: the work grows with the tile's
  // observations, not with the district's points times the tiles.
  std::set<uint64_t> seen;
  for (const auto& [id, image] : m.images)
    for (const ColmapPoint2D& p2 : image.points2d)
      if (p2.point3d_id != ColmapPoint2D{}.point3d_id) seen.insert(p2.point3d_id);
  for (uint64_t id : seen) {
    const auto point = all.points.find(id);
    if (point == all.points.end()) continue;
    ColmapPoint3D p = point->second;
    p.track.erase(std::remove_if(p.track.begin(), p.track.end(), [&](const auto& obs) { return !m.images.count(obs.first); }), p.track.end());
    if (!p.track.empty()) m.points[id] = std::move(p);
  }
  for (auto& [id, image] : m.images)
    for (ColmapPoint2D& p2 : image.points2d)
      if (p2.point3d_id != ColmapPoint2D{}.point3d_id && !m.points.count(p2.point3d_id)) p2.point3d_id = ColmapPoint2D{}.point3d_id;
  return m;
}

void write_tiles(const TilePlan& plan, const fs::path& tiles_dir) {
  const ColmapModel all = read_colmap(require_colmap_model(plan.scene));
  std::map<std::string, std::string> image_paths;  // name -> absolute source file
  for (const auto& [id, image] : all.images) image_paths[image.name] = fs::absolute(plan.scene / "images" / image.name).string();

  fs::create_directories(tiles_dir);
  for (const Tile& tile : plan.tiles) {
    const fs::path dir = tiles_dir / tile.name;
    for (const std::string& name : tile.images) {
      const fs::path link = dir / "images" / name;
      fs::create_directories(link.parent_path());
      if (fs::is_symlink(link) || fs::exists(link)) fs::remove(link);
      const auto source = image_paths.find(name);
      if (source == image_paths.end())
        fail((plan.scene / "sparse").string(), "tile " + tile.name + ": image '" + name + "' is not in the COLMAP model");
      fs::create_symlink(source->second, link);
    }
    const fs::path sparse = dir / "sparse" / "0";
    fs::create_directories(sparse);
    write_colmap_binary(sparse.string(), tile_colmap(all, tile.images));
    nlohmann::json scene = {{"city_model", plan.city_model}, {"lod", plan.lod}};
    if (!plan.city_transform.empty()) scene["city_transform"] = plan.city_transform;
    if (!plan.taxonomy.empty()) scene["taxonomy"] = plan.taxonomy;
    scene["tile"] = {{"name", tile.name}, {"buildings", tile.buildings},
                     {"district", plan.scene.string()}};
    write_text_atomic(SceneFiles{dir}.config(), scene.dump(2) + "\n");
    log_info(cat("tile: ", tile.name, ": ", tile.buildings.size(), " buildings, ", tile.images.size(), " images"));
  }
  write_tile_plan(tiles_dir / "tiles.json", plan);
}

}  // namespace cls
