#include "render/render_model.h"

#include <filesystem>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/run_layout.h"
#include "query/text_queries.h"
#include "splat/model_layout.h"
#include "splat/ply_gaussians.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

// train-rgb's summary.json "scene", if there is one.
std::string train_rgb_scene(const fs::path& dir) {
  const fs::path summary = dir / "summary.json";
  if (!fs::is_regular_file(summary)) return "";
  try {
    const nlohmann::json j = nlohmann::json::parse(read_text_file(summary));
    return j.value("scene", "");
  } catch (const nlohmann::json::exception& e) {
    fail(summary.string(), std::string("not valid JSON: ") + e.what());
  }
}

}  // namespace

RenderModel load_render_model(const std::string& path) {
  RenderModel m;
  const fs::path p(path);
  if (fs::is_regular_file(p)) {
    m.kind = "ply";
    m.ply = path;
  } else if (!fs::is_directory(p)) {
    fail(path, "no such file or directory (expected a 3DGS PLY or a model directory)");
  } else if (fs::is_regular_file(LanguageModelFiles{p}.model_json())) {
    m.kind = "language";
    m.language = load_language_model(path);
    m.ply = LanguageModelFiles{p}.geometry().string();
    m.gaussians = m.language->gaussians;
    m.recorded_scene = recorded_scene(m.language->info);
    return m;
  } else if (const fs::path layout = latest_layout_ply(p); !layout.empty()) {
    m.kind = "3dgs-layout";
    m.ply = layout.string();
  } else if (fs::is_regular_file(p / "point_cloud.ply")) {
    m.kind = "train-rgb";
    m.ply = (p / "point_cloud.ply").string();
  } else {
    fail(path, "not a model directory: no model.json (language model), point_cloud/iteration_N/point_cloud.ply "
               "(3DGS layout) or point_cloud.ply (train-rgb output)");
  }
  m.gaussians = read_gaussians_ply(m.ply);
  m.gaussians.validate(m.ply);
  if (m.kind != "ply") m.recorded_scene = train_rgb_scene(p);
  return m;
}

}  // namespace cls
