// The 3DGS output layout: cameras.json read back against the scene's poses, in the original's order and
// convention (utils/camera_utils.py camera_to_JSON: position = camera centre, rotation = camera-to-world).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "core/atomic_file.h"
#include "models/temp_dir.h"
#include "raycast/look_at.h"
#include "scene/view_selection.h"
#include "splat/model_layout.h"

namespace cls {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// A scene of `n` views named in reverse order, cameras on random positions looking at the origin.
Scene random_scene(int n) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-20, 20);
  Scene s;
  s.root = "/tmp/some_scene";
  for (int i = 0; i < n; ++i) {
    SceneView v;
    v.name = "sub/img_" + std::to_string(100 - i) + ".v2.jpg";
    v.camera = {100.0 + i, 101.0 + i, 40, 30, 80 + 2 * i, 60 + i};
    v.pose = look_at({u(rng), u(rng), 10 + u(rng)}, {0, 0, 0});
    s.views.push_back(v);
  }
  return s;
}

void expect_camera(const json& c, const SceneView& v) {
  const Vec3d centre = v.pose.center();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(c["position"][i].get<double>(), centre[i], 1e-9);
    // camera_to_JSON writes inv([R | t])[:3, :3] = R^T, row by row.
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(c["rotation"][i][j].get<double>(), v.pose.R.m[j][i], 1e-6);
  }
  EXPECT_EQ(c["width"], v.camera.width);
  EXPECT_EQ(c["height"], v.camera.height);
  EXPECT_DOUBLE_EQ(c["fx"].get<double>(), v.camera.fx);
  EXPECT_DOUBLE_EQ(c["fy"].get<double>(), v.camera.fy);
  // basename up to the first '.', as 3DGS's dataset reader names images
  const std::string file = fs::path(v.name).filename().string();
  EXPECT_EQ(c["img_name"], file.substr(0, file.find('.')));
}

TEST(ModelLayout, CamerasJsonIsTestThenTrainInTheOriginalConvention) {
  const Scene scene = random_scene(11);
  const ViewSplit split = split_views(scene, 4);
  ASSERT_EQ(split.test.size(), 3u);  // sorted indices 0, 4, 8
  const json cams = cameras_json(scene, 4);
  ASSERT_EQ(cams.size(), scene.views.size());
  size_t k = 0;
  for (const auto* list : {&split.test, &split.train})
    for (const SceneView* v : *list) {
      EXPECT_EQ(cams[k]["id"], k);
      expect_camera(cams[k], *v);
      ++k;
    }
}

TEST(ModelLayout, WritesThePlyAndCamerasAndFindsTheLatestIteration) {
  test::TempDir tmp;
  const Scene scene = random_scene(5);
  const fs::path ply = tmp.path / "point_cloud.ply";
  write_text_atomic(ply, "not really a PLY, the layout only links it");
  const fs::path target = write_model_layout(tmp.path, ply, scene, {30, 3, 8, false});
  EXPECT_EQ(target, tmp.path / "point_cloud" / "iteration_30" / "point_cloud.ply");
  EXPECT_TRUE(fs::equivalent(target, ply));  // a hard link, no copy
  EXPECT_EQ(write_model_layout(tmp.path, ply, scene, {30, 3, 8, false}), target);  // again: no stray temporary
  EXPECT_EQ(std::distance(fs::directory_iterator(target.parent_path()), fs::directory_iterator()), 1);

  const json cams = json::parse(read_text_file(tmp.path / "cameras.json"));
  const ViewSplit split = split_views(scene, 8);
  ASSERT_EQ(cams.size(), 5u);
  expect_camera(cams[0], *split.test[0]);
  for (size_t i = 0; i < split.train.size(); ++i) expect_camera(cams[i + 1], *split.train[i]);
  const std::string cfg = read_text_file(tmp.path / "cfg_args");
  EXPECT_NE(cfg.find("sh_degree=3"), std::string::npos) << cfg;
  EXPECT_NE(cfg.find("source_path='/tmp/some_scene'"), std::string::npos) << cfg;

  // A new layout replaces the folder's other iterations, also a higher one left by a longer earlier
  // schedule, which viewers (and latest_layout_ply) would open instead.
  write_model_layout(tmp.path, ply, scene, {100, 3, 8, false});
  EXPECT_FALSE(fs::exists(tmp.path / "point_cloud" / "iteration_30"));
  write_model_layout(tmp.path, ply, scene, {20, 3, 8, false});
  EXPECT_EQ(latest_layout_ply(tmp.path), tmp.path / "point_cloud" / "iteration_20" / "point_cloud.ply");
  EXPECT_FALSE(fs::exists(tmp.path / "point_cloud" / "iteration_100"));

  // Numeric, not lexicographic: iteration_100 beats iteration_30 (folders other tools wrote);
  // directories without a PLY do not count.
  write_model_layout(tmp.path, ply, scene, {100, 3, 8, false});
  fs::create_directories(tmp.path / "point_cloud" / "iteration_30");
  write_text_atomic(tmp.path / "point_cloud" / "iteration_30" / "point_cloud.ply", "");
  fs::create_directories(tmp.path / "point_cloud" / "iteration_500");
  fs::create_directories(tmp.path / "point_cloud" / "iteration_700x");
  write_text_atomic(tmp.path / "point_cloud" / "iteration_700x" / "point_cloud.ply", "");
  EXPECT_EQ(latest_layout_ply(tmp.path), tmp.path / "point_cloud" / "iteration_100" / "point_cloud.ply");
  EXPECT_EQ(latest_layout_ply(tmp.path / "nothing"), fs::path());
}

}  // namespace
}  // namespace cls
