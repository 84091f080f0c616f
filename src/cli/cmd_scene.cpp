// citylangsplat scene info DIR [--json] [-r N | --width W]
// citylangsplat scene convert DIR --out DIR --format bin|txt
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/strings.h"
#include "core/log.h"
#include "citymodel/city_model.h"
#include "georef/crs_name.h"
#include "georef/gps_footprint.h"
#include "scene/colmap.h"
#include "scene/exif_gps.h"
#include "scene/opf.h"
#include "scene/pix4d.h"
#include "scene/pix4d_project.h"
#include "scene/image_loader.h"
#include "scene/scene.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

// Cameras are counted by value: Pix4D gives every view its own camera, usually an identical one.
using CameraKey = std::tuple<int, int, int, std::vector<double>, double>;

int scene_info(int argc, char** argv) {
  Args args("scene info",
            "Summarize a scene: views, cameras and their models, sparse points, image sizes, the photos' EXIF GPS.");
  std::string dir;
  SceneOptions options;
  bool json = false, verify_images = false;
  std::string city, crs_override;
  args.positional("DIR", dir, "scene directory (COLMAP model in sparse/0, sparse or DIR; or a Pix4D project)")
      .flag("json", json, "print one JSON object instead of text")
      .bind("resolution", options.resolution_factor, "3DGS-style downscaling factor: 1, 2, 4 or 8")
      .short_name("r")
      .bind("width", options.target_width, "downscale to this image width instead (0 = off)")
      .flag("skip-image-check", options.check_images,
            "do not check that every image file exists (nor read the photos' EXIF GPS)", false)
      .flag("verify-images", verify_images,
            "decode every image (undistorted, downscaled) to find corrupt files before a long job")
      .bind("city", city, "city model: where the photos' GPS positions lie against it, in its CRS")
      .bind("crs", crs_override, "the city model's CRS when its file names none or another (EPSG:N; default: "
                                 "the file's srsName / referenceSystem)");
  if (!args.parse(argc, argv)) return 0;
  if (verify_images && !options.check_images)
    throw UsageError("scene info: --verify-images and --skip-image-check exclude each other");
  if (!city.empty() && !options.check_images)
    throw UsageError("scene info: --city needs the photos' GPS, which --skip-image-check does not read");
  const Scene scene = load_scene(dir, options);
  if (verify_images) {
    // One image at a time: a large scene never sits in memory.
    ImageLoader loader;
    Progress progress("verify images", scene.views.size(), "images");
    for (const SceneView& v : scene.views) {
      loader.load(v);
      progress.advance();
    }
  }

  std::map<CameraKey, int> cameras;
  std::map<std::string, int> models;
  std::map<std::pair<std::array<int, 2>, std::array<int, 2>>, int> sizes;  // (source, loaded) -> views
  for (const SceneView& v : scene.views) {
    const Camera& c = v.source_camera;
    if (cameras.emplace(CameraKey{int(c.model), c.width, c.height, c.params, v.source_radial_k3}, 0).second)
      ++models[camera_model_name(c.model) + (v.source_radial_k3 != 0 ? "+k3" : "")];
    ++sizes[{{c.width, c.height}, {v.camera.width, v.camera.height}}];
  }

  // The photos' EXIF GPS (what georeferencing starts from): how many carry a fix, and where.
  std::vector<GpsFix> fixes;
  if (options.check_images)
    for (const SceneView& v : scene.views)
      if (const std::optional<GpsFix> fix = read_exif_gps(v.image_path)) fixes.push_back(*fix);
  const GpsExtent gps = gps_extent(fixes);
  // Against the city model, in its CRS.
  nlohmann::json against = nullptr;
  std::string against_text;
  if (!city.empty()) {
    const SemanticMesh mesh = load_city_model(city, Taxonomy::builtin(), 0);
    const std::string crs_text = crs_override.empty() ? mesh.crs : crs_override;
    const CrsName crs = city_model_crs(city, mesh.crs, crs_override);
    const GpsProjection projection(crs.horizontal_epsg);
    const GpsFootprint f = gps_footprint(fixes, mesh, projection);
    against = {{"city", city}, {"crs", crs_text}, {"epsg", crs.horizontal_epsg}, {"fixes", f.fixes},
               {"box", f.box}, {"model_heights", f.model_heights}};
    const auto metres = [](double v) {
      char text[32];
      std::snprintf(text, sizeof text, "%.1f", v);
      return std::string(text);
    };
    against_text = cat("city:    ", city, " in EPSG:", crs.horizontal_epsg, " (", crs_text, "), heights ",
                       metres(f.model_heights[0]), "..", metres(f.model_heights[1]));
    if (f.fixes > 0) {
      against.update({{"median_distance", f.median_distance}, {"max_distance", f.max_distance}});
      against_text += cat("\n         the photos' GPS lies ", metres(f.median_distance), " (median), up to ",
                          metres(f.max_distance), " from the model's bounding box horizontally (CRS units)");
    }
    if (gps.with_altitude > 0)
      against_text += cat("; GPS altitudes ", metres(gps.altitude[0]), "..", metres(gps.altitude[1]));
  }

  // Photos in images/ the calibration left out (COLMAP often registers part of a phone set): unused.
  size_t unregistered = 0;
  if (const fs::path images = fs::path(scene.root) / "images"; scene.source != "opf" && fs::is_directory(images)) {
    std::set<std::string> registered;
    for (const SceneView& v : scene.views) registered.insert(fs::path(v.image_path).lexically_normal().string());
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(images, ec); it != fs::recursive_directory_iterator(); it.increment(ec)) {
      const std::string ext = ascii_lower(it->path().extension().string());
      const bool photo = ext == ".jpg" || ext == ".jpeg" || ext == ".png" || ext == ".tif" || ext == ".tiff";
      if (photo && it->is_regular_file(ec) && !registered.count(it->path().lexically_normal().string())) ++unregistered;
    }
  }
  nlohmann::json frame_json = nullptr;
  std::string frame_text;
  if (scene.frame) {
    const SceneFrame& f = *scene.frame;
    frame_json = {{"crs", f.crs}, {"scale", f.scale}, {"shift", {f.shift.x, f.shift.y, f.shift.z}}, {"source", f.source}};
    const std::string crs = f.crs.empty() ? "no CRS named" : f.crs.size() > 60 ? f.crs.substr(0, 57) + "..." : f.crs;
    char shift[128];
    std::snprintf(shift, sizeof shift, "%.3f %.3f %.3f", f.shift.x, f.shift.y, f.shift.z);
    frame_text = cat("frame:   scene = ", f.scale, " x CRS + (", shift, "), CRS ", crs, " (", f.source, ")");
  }

  if (json) {
    nlohmann::json gps_json = nullptr;  // null: the images were not read (--skip-image-check)
    if (options.check_images) {
      gps_json = {{"images", gps.fixes}, {"datums", gps.datums}};
      if (gps.fixes > 0) gps_json.update({{"latitude", gps.latitude}, {"longitude", gps.longitude}});
      if (gps.with_altitude > 0) gps_json["altitude"] = gps.altitude;
    }
    nlohmann::json sizes_json = nlohmann::json::array();
    for (const auto& [s, n] : sizes)
      sizes_json.push_back({{"source", {s.first[0], s.first[1]}}, {"loaded", {s.second[0], s.second[1]}}, {"views", n}});
    const nlohmann::json out = {{"root", scene.root},
                                {"source", scene.source},
                                {"views", scene.views.size()},
                                {"cameras", cameras.size()},
                                {"camera_models", models},
                                {"points", scene.points.size()},
                                {"unregistered_images", unregistered},
                                {"frame", frame_json},
                                {"image_sizes", sizes_json},
                                {"gps", gps_json},
                                {"gps_against_city", against}};
    std::printf("%s\n", out.dump().c_str());
    return 0;
  }
  std::printf("scene:   %s (%s)\n", scene.root.c_str(), scene.source.c_str());
  std::printf("views:   %zu\n", scene.views.size());
  std::printf("cameras: %zu (", cameras.size());
  bool first = true;
  for (const auto& [name, n] : models) {
    std::printf("%s%s x%d", first ? "" : ", ", name.c_str(), n);
    first = false;
  }
  std::printf(")\npoints:  %zu\n", scene.points.size());
  for (const auto& [s, n] : sizes)
    std::printf("images:  %d views %dx%d, loaded as %dx%d\n", n, s.first[0], s.first[1], s.second[0], s.second[1]);
  if (unregistered > 0)
    std::printf("         %zu more photos in images/ are not in the calibration (not registered): they are not used\n",
                unregistered);
  if (!frame_text.empty()) std::printf("%s\n", frame_text.c_str());
  if (!options.check_images) {
    std::printf("gps:     not read (--skip-image-check)\n");
  } else if (gps.fixes == 0) {
    std::printf("gps:     none of the %zu images carries an EXIF GPS position\n", scene.views.size());
  } else {
    std::printf("gps:     %zu of %zu images, latitude %.7f..%.7f, longitude %.7f..%.7f", gps.fixes, scene.views.size(),
                gps.latitude[0], gps.latitude[1], gps.longitude[0], gps.longitude[1]);
    if (gps.with_altitude > 0) std::printf(", altitude %.2f..%.2f m", gps.altitude[0], gps.altitude[1]);
    for (const auto& [datum, n] : gps.datums) std::printf(", datum %s x%d", datum.c_str(), n);
    std::printf("\n");
  }
  if (!against_text.empty()) std::printf("%s\n", against_text.c_str());
  return 0;
}

int scene_convert(int argc, char** argv) {
  Args args("scene convert", "Write a scene's cameras and poses as a COLMAP model (lossless for COLMAP input).");
  std::string dir, out, format = "bin";
  args.positional("DIR", dir, "scene directory (COLMAP model, OPF or Pix4D project)")
      .bind("out", out, "output model directory (cameras, images, points3D are written into it)")
      .required()
      .bind("format", format, "output format: bin or txt", choice_codec({"bin", "txt"}));
  if (!args.parse(argc, argv)) return 0;

  ColmapModel model;
  const std::string model_dir = find_colmap_model(dir);
  const std::string opf = model_dir.empty() ? find_opf_project(dir) : std::string();
  if (!model_dir.empty()) {
    model = read_colmap(model_dir);
  } else if (!opf.empty()) {  // cameras as Pix4D's, with the tie points (no tracks)
    const OpfProject project = read_opf_project(opf);
    model = pix4d_to_colmap(project.views, opf);
    for (const OpfPoint& p : project.points) {
      const uint64_t id = model.points.size() + 1;
      model.points[id] = ColmapPoint3D{id, p.xyz, p.rgb, 0, {}};
    }
  } else {  // cameras as Pix4D's, with the densified cloud in the cameras' frame (no tracks)
    const Pix4dProject project = find_pix4d_project(dir);
    if (project.calibration.empty())
      fail(dir, "no COLMAP model, OPF project or Pix4D calibrated_camera_parameters.txt found");
    model = pix4d_to_colmap(read_pix4d_calibrated_cameras(project.calibration), project.calibration);
    const PointCloud cloud = read_pix4d_cloud(project, SceneOptions{}.max_cloud_points);
    for (size_t i = 0; i < cloud.xyz.size(); ++i)
      model.points[i + 1] = ColmapPoint3D{i + 1, {cloud.xyz[i].x, cloud.xyz[i].y, cloud.xyz[i].z}, cloud.rgb[i], 0, {}};
  }
  (format == "bin" ? write_colmap_binary : write_colmap_text)(out, model);
  log_info(cat("wrote ", model.cameras.size(), " cameras, ", model.images.size(), " images, ", model.points.size(),
               " points to ", out, " (", format, ")"));
  return 0;
}

}  // namespace

int cmd_scene(int argc, char** argv) {
  const std::string usage =
      "usage: citylangsplat scene info DIR [options]\n"
      "       citylangsplat scene convert DIR --out DIR [--format bin|txt]\n"
      "'citylangsplat scene <info|convert> --help' shows the options.\n";
  if (argc < 2) throw UsageError("scene: missing subcommand\n" + usage);
  const std::string sub = argv[1];
  if (sub == "-h" || sub == "--help") {
    std::printf("%s", usage.c_str());
    return 0;
  }
  if (sub == "info") return scene_info(argc - 1, argv + 1);
  if (sub == "convert") return scene_convert(argc - 1, argv + 1);
  throw UsageError("scene: unknown subcommand '" + sub + "'\n" + usage);
}

}  // namespace cls
