#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "core/error.h"
#include "scene/path_query.h"
#include "core/log.h"
#include "scene/colmap.h"
#include "scene/image_loader.h"
#include "scene/opf.h"
#include "scene/pix4d.h"
#include "scene/pix4d_project.h"
#include "scene/undistort.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

// The loaded-resolution pinhole camera of a source camera.
PinholeCamera loaded_camera(const Camera& camera, double radial_k3, const SceneOptions& options,
                            const std::string& source) {
  return scale_to_resolution(undistorted_pinhole(lens_from_camera(camera, radial_k3), source), options);
}

SceneView make_view(uint32_t image_id, const std::string& name, const fs::path& image_dir, const Camera& camera,
                    double radial_k3, const PinholeCamera& loaded, const Pose& pose) {
  SceneView v;
  v.image_id = image_id;
  v.name = name;
  v.image_path = (image_dir / name).string();
  v.source_camera = camera;
  v.source_radial_k3 = radial_k3;
  v.camera = loaded;
  v.pose = pose;
  return v;
}

void load_colmap(Scene& scene, const std::string& model_dir, const fs::path& image_dir, const SceneOptions& options) {
  const ColmapModel model = read_colmap(model_dir);
  scene.source = is_file(fs::path(model_dir) / "cameras.bin") ? "colmap-bin" : "colmap-txt";
  // One undistorted camera per COLMAP camera, shared by its images.
  std::map<uint32_t, PinholeCamera> loaded;
  for (const auto& [id, cam] : model.cameras)
    loaded[id] = loaded_camera(cam, 0, options, model_dir + " camera " + std::to_string(id));
  for (const auto& [id, im] : model.images)
    scene.views.push_back(make_view(id, im.name, image_dir, model.cameras.at(im.camera_id), 0,
                                    loaded.at(im.camera_id), im.pose()));
  for (const auto& [id, p] : model.points)
    scene.points.push_back(SparsePoint{id, Vec3d{p.xyz[0], p.xyz[1], p.xyz[2]}, p.rgb, p.error});
}

// The WGS 84 ellipsoid's semi-axes, metres.
constexpr double kWgs84A = 6378137.0, kWgs84B = 6356752.314245;

// Height of a point, read as ECEF, above the WGS 84 ellipsoid along the geocentric radius: within
// metres of the geodetic height near the surface, which is all the test below needs.
double height_above_ellipsoid(const Vec3d& p) {
  const double r = norm(p), sin_lat = p.z / r, cos_lat = std::hypot(p.x, p.y) / r;
  return r - kWgs84A * kWgs84B / std::hypot(kWgs84B * cos_lat, kWgs84A * sin_lat);
}

// A model that COLMAP's model_aligner put into a CRS (reference positions in a projected CRS, or GPS
// with --alignment_type ecef) has coordinates of millions of metres, which the float32 training cannot
// hold (a 5,500 km northing keeps half a metre). It is recentred on its cameras, in double, and the frame
// says where it lay: ECEF (EPSG:4978) when its cameras sit on the Earth's surface read that way, else a
// projected CRS the model does not name (the city model's, or georef --crs). No model in SfM's
// arbitrary units reaches 100 km from its origin.
void recentre_absolute_model(Scene& scene, const std::string& model_dir) {
  if (scene.views.empty()) return;
  Vec3d mean{};
  for (const SceneView& v : scene.views) mean = mean + v.pose.center() * (1.0 / scene.views.size());
  if (std::max({std::abs(mean.x), std::abs(mean.y), std::abs(mean.z)}) < 1e5) return;
  const Vec3d shift{-std::round(mean.x), -std::round(mean.y), -std::round(mean.z)};
  for (SceneView& v : scene.views) v.pose.t = v.pose.t - v.pose.R * shift;
  for (SparsePoint& p : scene.points) p.xyz = p.xyz + shift;
  const double h = height_above_ellipsoid(mean);
  const bool ecef = h > -1000 && h < 10000;
  scene.frame = SceneFrame{ecef ? "EPSG:4978" : "", 1, shift, model_dir};
  log_info(cat("scene: the COLMAP model lies in absolute coordinates (", ecef ? "ECEF" : "a projected CRS",
               ", as model_aligner writes them): recentred by ", static_cast<long long>(-shift.x), " ",
               static_cast<long long>(-shift.y), " ", static_cast<long long>(-shift.z),
               ", which the scene's frame keeps"));
}

// The cloud must lie where the cameras are: a cloud in another frame (an offset not subtracted, another
// CRS) would start the Gaussians far away from everything the photos see.
void check_cloud_near_cameras(const Scene& scene, const std::vector<std::string>& files) {
  if (scene.points.empty() || scene.views.empty()) return;
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi = -lo, mean{};
  for (const SceneView& v : scene.views) {
    const Vec3d c = v.pose.center();
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
    mean = mean + c * (1.0 / scene.views.size());
  }
  std::vector<double> d;
  for (const SparsePoint& p : scene.points) d.push_back(norm(p.xyz - mean));
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  const double spread = norm(hi - lo), median = d[d.size() / 2];
  if (median > 10 * spread + 1000)
    fail(files.front(), cat("the point cloud lies ", median, " from the cameras (which span ", spread,
                            "): is it in the project's output CRS, with the offset in *_offset.xyz?"));
}

// Pix4D calibrates every image separately, so each view has its own camera. The project's densified cloud,
// when there is one, gives the points; its offset and output CRS, the frame.
void load_pix4d(Scene& scene, const Pix4dProject& project, const fs::path& image_dir, const SceneOptions& options) {
  scene.source = "pix4d";
  const std::string& file = project.calibration;
  uint32_t id = 0;
  for (const Pix4dView& p : read_pix4d_calibrated_cameras(file)) {
    const PinholeCamera loaded = loaded_camera(p.camera, p.radial_k3, options, file + " camera '" + p.name + "'");
    scene.views.push_back(make_view(++id, p.name, image_dir, p.camera, p.radial_k3, loaded, p.pose));
  }
  if (!project.offset_file.empty() || !project.crs_file.empty())
    scene.frame = SceneFrame{project.crs, 1, -project.offset, project.offset_file.empty() ? project.crs_file : project.offset_file};
  if (project.clouds.empty()) return;
  const PointCloud cloud = read_pix4d_cloud(project, options.max_cloud_points);
  for (size_t i = 0; i < cloud.xyz.size(); ++i) scene.points.push_back(SparsePoint{i + 1, cloud.xyz[i], cloud.rgb[i], 0});
  check_cloud_near_cameras(scene, project.clouds);
  log_info(cat("scene: ", scene.points.size(), " of the ", cloud.total, " points of the densified cloud (",
               project.clouds.size(), " file(s) from ", project.clouds.front(), ")",
               scene.points.size() < cloud.total ? cat("; thinned to at most ", options.max_cloud_points) : ""));
}

// An OPF project: per-view cameras (as Pix4D), images where its camera list says, tie points.
void load_opf(Scene& scene, const std::string& file, const SceneOptions& options) {
  scene.source = "opf";
  const OpfProject project = read_opf_project(file);
  for (size_t i = 0; i < project.views.size(); ++i) {
    const Pix4dView& p = project.views[i];
    const PinholeCamera loaded = loaded_camera(p.camera, p.radial_k3, options, file + " camera '" + p.name + "'");
    SceneView v = make_view(static_cast<uint32_t>(i + 1), p.name, {}, p.camera, p.radial_k3, loaded, p.pose);
    v.image_path = project.images[i];
    scene.views.push_back(std::move(v));
  }
  uint64_t id = 0;
  for (const OpfPoint& p : project.points)
    scene.points.push_back(SparsePoint{++id, Vec3d{p.xyz[0], p.xyz[1], p.xyz[2]}, p.rgb, 0});
  // The processing CRS is base_to_canonical of the CRS: a similarity only without swap_xy (a
  // reflection) and with one scale for all axes.
  const OpfReferenceFrame& f = project.frame;
  if (f.crs.empty()) return;
  if (f.swap_xy || f.scale[0] != f.scale[1] || f.scale[0] != f.scale[2] || !(f.scale[0] > 0))
    log_warn(cat(file, ": the scene reference frame swaps x and y or scales the axes differently; its CRS is not "
                       "used as the scene's frame"));
  else
    scene.frame = SceneFrame{f.crs, f.scale[0], Vec3d{f.shift[0], f.shift[1], f.shift[2]}, file};
}

}  // namespace

Scene load_scene(const std::string& dir, const SceneOptions& options) {
  check_scene_options(options);
  if (dir.empty()) throw Error("no scene directory given");
  const fs::path root = fs::absolute(dir);
  if (!is_dir(root)) fail(dir, "scene directory not found");
  Scene scene;
  scene.root = root.string();
  const fs::path image_dir = root / "images";

  const std::string model_dir = find_colmap_model(root.string());
  const std::string opf = model_dir.empty() ? find_opf_project(root.string()) : std::string();
  if (!model_dir.empty()) {
    load_colmap(scene, model_dir, image_dir, options);
    recentre_absolute_model(scene, model_dir);
  } else if (!opf.empty()) {
    load_opf(scene, opf, options);
  } else {
    const Pix4dProject pix4d = find_pix4d_project(root.string());
    if (pix4d.calibration.empty())
      fail(dir, "no camera model found: expected a COLMAP model (cameras/images/points3D .bin or .txt) in sparse/0, "
                "sparse or the directory itself, an OPF project (*.opf) or a Pix4D *calibrated_camera_parameters.txt");
    load_pix4d(scene, pix4d, image_dir, options);
  }
  // Views in name order, as 3DGS sorts them, whatever the ids.
  std::sort(scene.views.begin(), scene.views.end(),
            [](const SceneView& a, const SceneView& b) { return a.name < b.name; });

  if (options.check_images) {
    if (scene.source != "opf" && !is_dir(image_dir)) fail(image_dir.string(), "image folder not found");
    for (const SceneView& v : scene.views)
      if (!is_file(v.image_path)) fail(v.image_path, "image not found (view '" + v.name + "')");
  }
  log_verbose(cat("scene ", dir, ": ", scene.views.size(), " views, ", scene.points.size(), " sparse points (",
                  scene.source, ")"));
  return scene;
}

}  // namespace cls
