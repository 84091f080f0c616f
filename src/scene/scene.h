#pragma once
// A calibrated scene: undistorted pinhole views with poses, sparse points, and lazily loaded images.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/camera.h"

namespace cls {

struct SceneView {
  uint32_t image_id = 0;
  std::string name;        // image file name as in the model (may contain sub-folders)
  std::string image_path;  // absolute path of the source image file
  Camera source_camera;    // the camera as stored (possibly distorted), at full resolution
  double source_radial_k3 = 0;  // third radial coefficient beyond COLMAP's OPENCV model (Pix4D only)
  PinholeCamera camera;    // undistorted pinhole intrinsics at the loaded resolution
  Pose pose;               // world -> camera
};

struct SparsePoint {
  uint64_t id = 0;
  Vec3d xyz{};
  std::array<uint8_t, 3> rgb{};
  double error = 0;
};

struct SceneOptions {
  int resolution_factor = 1;  // 3DGS-style -r 1|2|4|8: divide the image size by this
  int target_width = 0;       // alternatively: resize so that width == target_width (0 = off)
  bool check_images = true;   // fail early if an image file is missing
  // A densified cloud (PIX4Dmapper) is thinned to this many points (every k-th): the Gaussians
  // start from it, and 3DGS scenes start from 0.1-1 M points.
  uint64_t max_cloud_points = 1000000;
  // Without a factor or a target width, photos whose long side exceeds this are loaded at it (0 = off),
  // as the 3DGS reference code loads photos wider than 1600 px at 1600 unless -r is given.
  int max_side = 0;
  // Without a factor or a target width, photos taller than this are loaded at it as well (0 = off), as
  // LangSplat extracts its features from photos taller than 1080 px at 1080 ("1080P"); with max_side,
  // the stronger of the two reductions.
  int max_height = 0;
};

// Where the scene frame lies in a CRS, when its source says so: scene = scale * crs + shift.
// PIX4Dmapper: its offset (scale 1, shift -offset) and output CRS; OPF: the scene reference frame;
// a COLMAP model in absolute coordinates (model_aligner): the shift that recentred it at load.
struct SceneFrame {
  std::string crs;     // as the source writes it (WKT, EPSG:N, ...); "" when it names none
  double scale = 1;
  Vec3d shift{};
  std::string source;  // the file that says so
};

struct Scene {
  std::string root;
  std::string source;  // "colmap-bin", "colmap-txt", "opf" or "pix4d"
  std::vector<SceneView> views;
  std::vector<SparsePoint> points;
  std::optional<SceneFrame> frame;
};

// Loads a scene directory. Looks for, in order: DIR/sparse/0, DIR/sparse, DIR (COLMAP, binary
// preferred over text), an OPF project DIR/*.opf (opf.h), then a Pix4D calibrated_camera_parameters.txt
// under DIR (with the project's offset, output CRS and densified cloud: pix4d_project.h). Images are
// looked up under DIR/images (OPF: where its camera list says). Distorted cameras become pinhole views
// (see undistort.h). A COLMAP model in absolute coordinates is recentred (Scene::frame says by what).
// Any problem is a cls::Error naming the file and what is wrong.
Scene load_scene(const std::string& dir, const SceneOptions& options = {});

}  // namespace cls
