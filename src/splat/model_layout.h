#pragma once
// The output layout of the original 3DGS (graphdeco-inria/gaussian-splatting), which its SIBR viewer,
// SuperSplat and other tools open:
//   DIR/point_cloud/iteration_N/point_cloud.ply   the model (splat/ply_gaussians.h)
//   DIR/cameras.json                               the scene's cameras (utils/camera_utils.py camera_to_JSON)
//   DIR/cfg_args                                   the training arguments as a Python Namespace repr
//                                                  (SIBR reads source_path, sh_degree, white_background)
// cameras.json: a list, the test views first, then the training views (scene/__init__.py), each sorted by
// name as split_views splits them; per camera {"id": index in the list, "img_name": file name up to its
// first '.', "width", "height", "position": camera centre [3], "rotation": camera-to-world rotation [3][3]
// (rows; = R^T of our world-to-camera pose), "fy", "fx"}. Sizes and focal lengths are the loaded
// (undistorted, possibly downscaled) pinhole cameras the model was trained with.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace cls {

// One camera_to_JSON entry.
nlohmann::json camera_json(int id, const SceneView& view);
// All cameras in 3DGS's order for the given split.
nlohmann::json cameras_json(const Scene& scene, int test_every);

struct ModelLayoutOptions {
  int iteration = 0;
  int sh_degree = 3;
  int test_every = 8;
  bool white_background = false;
};

// Writes the layout into `dir` for the PLY at `ply` (hard-linked into point_cloud/iteration_N/, copied
// where the file system has no hard links); every file atomically. Other point_cloud/iteration_* folders
// are removed: one model per folder. Returns the layout's PLY path.
std::filesystem::path write_model_layout(const std::filesystem::path& dir, const std::filesystem::path& ply,
                                         const Scene& scene, const ModelLayoutOptions& options);

// DIR/point_cloud/iteration_N/point_cloud.ply with the highest N (searchForMaxIteration); "" if none.
std::filesystem::path latest_layout_ply(const std::filesystem::path& dir);

}  // namespace cls
