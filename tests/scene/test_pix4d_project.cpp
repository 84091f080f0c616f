// A PIX4Dmapper project as its outputs lay it out (scene/pix4d_project.h): the offset and output CRS
// become the scene's frame, and the densified cloud (LAS parts in the output CRS, or PLY offset by its
// sidecar) the scene's points in the calibration's frame. The files are written here byte by byte from
// the LAS and PLY specifications, with coordinates worked out by hand.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.h"
#include "core/log.h"
#include "scene/pix4d_project.h"
#include "scene/scene.h"
#include "scene_test_util.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

const Vec3d kOffset{356000, 5645000, 100};

// Points in the calibration's (offset) frame, near the camera at (1, 2, 30) looking down.
const std::vector<Vec3d> kPoints = {{0, 0, 0}, {1.25, -2.5, 0.75}, {3, 4, 5.5}, {-6.125, 1, 0.25}, {2, 2, 2}};

fs::path project(const std::string& name) {
  const fs::path dir = test::fresh_dir(name);
  const fs::path params = dir / "1_initial" / "params";
  fs::create_directories(params);
  write_text_atomic(params / "site_calibrated_camera_parameters.txt",
                    "a.png 100 80\n90 0 50\n0 90 40\n0 0 1\n0 0 0\n0 0\n1 2 30\n1 0 0\n0 -1 0\n0 0 -1\n");
  write_text_atomic(params / "site_offset.xyz", "356000.000 5645000.000 100.000\n");
  write_text_atomic(params / "site_wkt.prj", "PROJCS[\"ETRS89 / UTM zone 32N\"]\n");
  fs::create_directories(dir / "images");
  cv::imwrite((dir / "images" / "a.png").string(), cv::Mat(80, 100, CV_8UC3, cv::Scalar(0, 0, 0)));
  return dir;
}

}  // namespace

TEST(Pix4dProject, LasPartsInTheOutputCrsBecomeThePointsOfTheOffsetFrame) {
  const fs::path dir = project("pix4d_las");
  const fs::path clouds = dir / "2_densification" / "point_cloud";
  fs::create_directories(clouds);
  std::vector<Vec3d> crs;
  for (const Vec3d& p : kPoints) crs.push_back(p + kOffset);
  // two parts, as Pix4D splits large clouds
  write_text_atomic(clouds / "site_group1_densified_point_cloud_part_1.las", test::las_file({crs.begin(), crs.begin() + 3}, 0));
  write_text_atomic(clouds / "site_group1_densified_point_cloud_part_2.las", test::las_file({crs.begin() + 3, crs.end()}, 3));

  const Scene s = load_scene(dir.string());
  EXPECT_EQ(s.source, "pix4d");
  ASSERT_TRUE(s.frame.has_value());
  EXPECT_EQ(s.frame->crs, "PROJCS[\"ETRS89 / UTM zone 32N\"]");
  EXPECT_EQ(s.frame->scale, 1.0);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(s.frame->shift[k], -kOffset[k]);
  ASSERT_EQ(s.points.size(), kPoints.size());
  for (size_t i = 0; i < kPoints.size(); ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.points[i].xyz[k], kPoints[i][k], 1e-6) << i << " " << k;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(s.points[i].rgb[c], 10 * (c + 1) * i) << i;  // 16 bit -> 8 bit
  }

  // A budget of 2 points keeps every k-th of the union.
  SceneOptions few;
  few.max_cloud_points = 2;
  const Scene thin = load_scene(dir.string(), few);
  ASSERT_LE(thin.points.size(), 2u);
  ASSERT_GE(thin.points.size(), 1u);
  EXPECT_NEAR(thin.points[0].xyz.x, kPoints[0].x, 1e-6);

  // Without the offset file the cloud lies 5.6 km from the cameras: refused, naming the cloud.
  fs::remove(dir / "1_initial" / "params" / "site_offset.xyz");
  test::expect_error([&] { load_scene(dir.string()); },
                     {"site_group1_densified_point_cloud_part_1.las: the point cloud lies", "*_offset.xyz"});
  fs::remove_all(dir);
}

TEST(Pix4dProject, PlyCloudsAddTheirSidecarOffset) {
  const fs::path dir = project("pix4d_ply");
  const fs::path clouds = dir / "2_densification" / "point_cloud";
  fs::create_directories(clouds);
  // PLY as Pix4D writes it: floats relative to NAME_ply_offset.xyz.
  const Vec3d ply_offset{356010, 5645020, 90};
  std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(kPoints.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar diffuse_red\n"
                    "property uchar diffuse_green\nproperty uchar diffuse_blue\nend_header\n";
  for (size_t i = 0; i < kPoints.size(); ++i) {
    const Vec3d p = kPoints[i] + kOffset - ply_offset;
    ply += cat(p.x, " ", p.y, " ", p.z, " ", i, " ", 2 * i, " ", 3 * i, "\n");
  }
  write_text_atomic(clouds / "site_group1_densified_point_cloud.ply", ply);
  write_text_atomic(clouds / "site_group1_densified_point_cloud_ply_offset.xyz", "356010 5645020 90\n");
  const Scene s = load_scene(dir.string());
  ASSERT_EQ(s.points.size(), kPoints.size());
  for (size_t i = 0; i < kPoints.size(); ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.points[i].xyz[k], kPoints[i][k], 1e-5) << i << " " << k;
    EXPECT_EQ(s.points[i].rgb[1], 2 * i);
  }
  write_text_atomic(dir / "1_initial" / "params" / "site_offset.xyz", "356000 5645000\n");
  test::expect_error([&] { load_scene(dir.string()); }, {"site_offset.xyz: a Pix4D offset file holds three finite numbers"});
  fs::remove_all(dir);
}

TEST(Pix4dProject, ACalibrationAloneHasNoFrameAndNoPoints) {
  const fs::path dir = project("pix4d_bare");
  fs::remove(dir / "1_initial" / "params" / "site_offset.xyz");
  fs::remove(dir / "1_initial" / "params" / "site_wkt.prj");
  const Scene s = load_scene(dir.string());
  EXPECT_FALSE(s.frame.has_value());
  EXPECT_TRUE(s.points.empty());
  fs::remove_all(dir);
}
