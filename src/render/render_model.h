#pragma once
// What `render` can be pointed at, resolved into the Gaussians to draw and, where there is one, the
// language field.
#include <optional>
#include <string>

#include "language/language_model.h"
#include "splat/gaussians.h"

namespace cls {

struct RenderModel {
  std::string kind;  // "ply", "3dgs-layout", "train-rgb" or "language"
  std::string ply;   // the PLY whose Gaussians (and SH colours) are drawn
  GaussianModel gaussians;
  std::optional<LanguageModel> language;  // kind "language" only
  std::string recorded_scene;             // the scene the model records (model.json / summary.json), or ""
};

// `path` is a 3DGS PLY; a directory with model.json (a language model: its frozen geometry PLY carries
// the photometric model's SH colours); a 3DGS layout (point_cloud/iteration_N/point_cloud.ply, the
// highest N); or a train-rgb output (point_cloud.ply), in that order. cls::Error naming `path` otherwise.
RenderModel load_render_model(const std::string& path);

}  // namespace cls
