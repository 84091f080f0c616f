#pragma once
// `citylangsplat render`: pictures of a trained model for people and for the 3DGS ecosystem. Per view
// the RGB render beside the photo with PSNR / SSIM, expected depth, a PCA picture of each language
// level, relevance maps of text queries and label maps beside the projected ground truth; optionally a
// camera path (orbit or interpolation through the scene's poses) as PNG frames and MP4. Everything is
// described by OUT/render.json. See docs/render.md.
#include <nlohmann/json.hpp>

#include "render/render_model.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace cls {

struct RenderOptions {
  std::string model;             // 3DGS PLY, train-rgb output, 3DGS layout or language model dir
  std::string scene_dir;         // empty: the scene the model records
  std::string out_dir;
  std::string views = "test";    // "test" (every test_every-th by name, as train-rgb), "all", or comma-separated names
  std::vector<std::string> what; // rgb, depth, features, relevance:TEXT (repeatable), labels; empty: what the inputs allow
  std::string labels_dir;        // `raycast` output (OUT/<view>/level1.png ... + legend.json); empty: none
  std::string gt_points;         // labelled point cloud; empty: SCENE/gt/points.ply when it exists
  std::string taxonomy_path;     // empty: the label maps' legend, else the model's, else the built-in one
  std::string path;              // "", "orbit" or "interpolate"
  int frames = 120;
  double fps = 30;
  int test_every = 8;
  int resolution = 1;            // 3DGS-style image downscaling (as train-rgb --resolution)
  bool white_background = false;
};

// A --what list split at commas; a comma inside a relevance text stays there ("relevance:red roof, tiles,depth"
// -> "relevance:red roof, tiles", "depth"): an item that names nothing known continues the text before it.
std::vector<std::string> split_what(const std::string& what);

// Writes everything under options.out_dir and returns what it wrote to OUT/render.json (paths relative
// to OUT). cls::UsageError for bad options (unknown view or --what item, a language output asked of a
// photometric model), cls::Error naming the file for unreadable inputs.
nlohmann::json render_views(const RenderOptions& options);

// The same on a loaded model and scene (options.model names the model in the record and finds a language
// model's taxonomy; options.scene_dir and resolution are the scene's business here). What `run` calls
// with the scene it already holds.
nlohmann::json render_views(const RenderModel& model, const Scene& scene, const RenderOptions& options);

}  // namespace cls
