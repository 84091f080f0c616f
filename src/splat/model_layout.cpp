#include "splat/model_layout.h"

#include <cstdio>

#include "core/atomic_file.h"
#include "core/error.h"
#include "scene/view_selection.h"

namespace cls {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Python's repr of a str (single quotes; enough for paths without quotes or backslashes).
std::string py_str(const std::string& s) { return "'" + s + "'"; }

}  // namespace

json camera_json(int id, const SceneView& view) {
  const Mat3d c2w = transpose(view.pose.R);
  const Vec3d c = view.pose.center();
  json rotation = json::array();
  for (int i = 0; i < 3; ++i) rotation.push_back({c2w.m[i][0], c2w.m[i][1], c2w.m[i][2]});
  const std::string file = fs::path(view.name).filename().string();
  return {{"id", id},
          {"img_name", file.substr(0, file.find('.'))},  // os.path.basename(path).split(".")[0]
          {"width", view.camera.width},
          {"height", view.camera.height},
          {"position", {c.x, c.y, c.z}},
          {"rotation", rotation},
          {"fy", view.camera.fy},
          {"fx", view.camera.fx}};
}

json cameras_json(const Scene& scene, int test_every) {
  const ViewSplit split = split_views(scene, test_every);
  json cams = json::array();
  for (const auto* list : {&split.test, &split.train})
    for (const SceneView* v : *list) cams.push_back(camera_json(int(cams.size()), *v));
  return cams;
}

fs::path write_model_layout(const fs::path& dir, const fs::path& ply, const Scene& scene,
                            const ModelLayoutOptions& o) {
  const fs::path target = dir / "point_cloud" / ("iteration_" + std::to_string(o.iteration)) / "point_cloud.ply";
  fs::create_directories(target.parent_path());
  // rename(2) onto another link of the same file would leave the temporary behind.
  if (!(fs::exists(target) && fs::equivalent(target, ply))) write_atomic(target, [&](const fs::path& tmp) {
    std::error_code ec;
    fs::create_hard_link(ply, tmp, ec);
    if (ec && !fs::copy_file(ply, tmp, ec)) fail(ply.string(), "cannot link or copy to " + target.string() + ": " + ec.message());
  });
  // One model per folder: an iteration_M left by an earlier, longer schedule would be the "latest" that
  // viewers (and latest_layout_ply) open instead of this one.
  for (const auto& e : fs::directory_iterator(target.parent_path().parent_path()))
    if (e.path() != target.parent_path() && e.path().filename().string().rfind("iteration_", 0) == 0)
      fs::remove_all(e.path());
  write_text_atomic(dir / "cameras.json", cameras_json(scene, o.test_every).dump() + "\n");
  // What 3DGS's train.py writes (str(Namespace(**vars(args)))), reduced to the fields viewers read.
  const std::string cfg = "Namespace(data_device='cpu', eval=" + std::string(o.test_every > 0 ? "True" : "False") +
                          ", images='images', model_path=" + py_str(fs::absolute(dir).string()) +
                          ", resolution=-1, sh_degree=" + std::to_string(o.sh_degree) +
                          ", source_path=" + py_str(fs::absolute(scene.root).string()) +
                          ", white_background=" + (o.white_background ? "True" : "False") + ")";
  write_text_atomic(dir / "cfg_args", cfg);
  return target;
}

fs::path latest_layout_ply(const fs::path& dir) {
  const fs::path root = dir / "point_cloud";
  if (!fs::is_directory(root)) return {};
  long best = -1;
  fs::path found;
  for (const auto& e : fs::directory_iterator(root)) {
    const std::string name = e.path().filename().string();
    long n = -1;
    char rest = 0;
    if (std::sscanf(name.c_str(), "iteration_%ld%c", &n, &rest) != 1 || n <= best) continue;
    if (!fs::is_regular_file(e.path() / "point_cloud.ply")) continue;
    best = n;
    found = e.path() / "point_cloud.ply";
  }
  return found;
}

}  // namespace cls
