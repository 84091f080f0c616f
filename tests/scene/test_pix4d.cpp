#include <gtest/gtest.h>

#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.h"
#include "scene/image_loader.h"
#include "scene/pix4d.h"
#include "scene/scene.h"
#include "scene/undistort.h"
#include "scene_test_util.h"

namespace fs = std::filesystem;
using namespace cls;
using cls::test::expect_error;

namespace {

// Header as Pix4D writes it, then two cameras: a nadir one with every distortion term, and a
// distortion-free one whose name contains a space.
const char* kCalibration =
    "fileName imageWidth imageHeight \n"
    "camera matrix K [3x3]\n"
    "radial distortion [3x1]\n"
    "tangential distortion [2x1]\n"
    "camera position t [3x1]\n"
    "camera rotation R [3x3]\n"
    "camera model m = K [R|-Rt] X\n"
    "\n"
    "nadir.jpg 1000 800\n"
    "1000 0 500\n"
    "0 1000 400\n"
    "0 0 1\n"
    "0.5 0.25 0.125\n"
    "0.01 -0.02\n"
    "10 20 100\n"
    "1 0 0\n"
    "0 -1 0\n"
    "0 0 -1\n"
    "oblique view.jpg 640 480\n"
    "800 0 320\n"
    "0 810 240\n"
    "0 0 1\n"
    "0 0 0\n"
    "0 0\n"
    "1 2 3\n"
    "1 0 0\n"
    "0 1 0\n"
    "0 0 1\n";

}  // namespace

TEST(Pix4d, ParsesAndProjectsAsHandComputed) {
  const auto views = parse_pix4d_calibrated_cameras(kCalibration, "calib.txt");
  ASSERT_EQ(views.size(), 2u);
  const Pix4dView& v = views[0];
  EXPECT_EQ(v.name, "nadir.jpg");
  EXPECT_EQ(v.camera.model, CameraModel::OpenCV);
  EXPECT_EQ(v.camera.width, 1000);
  EXPECT_EQ(v.camera.params, (std::vector<double>{1000, 1000, 500, 400, 0.5, 0.25, 0.01, -0.02}));
  EXPECT_EQ(v.radial_k3, 0.125);
  const Vec3d c = v.pose.center();
  EXPECT_NEAR(c.x, 10, 1e-12);
  EXPECT_NEAR(c.y, 20, 1e-12);
  EXPECT_NEAR(c.z, 100, 1e-12);

  // X = (12, 17, 0): R (X - C) = (2, 3, 100), normalized (0.02, 0.03), r2 = 0.0013,
  // radial = 0.5 r2 + 0.25 r2^2 + 0.125 r2^3 = 0.000650422774625
  // xd = 0.02 (1 + radial) + 2 T1 x y + T2 (r2 + 2 x^2) = 0.02 + 0.0000130084554925 + 0.000012 - 0.000042
  // yd = 0.03 (1 + radial) + T1 (r2 + 2 y^2) + 2 T2 x y = 0.03 + 0.00001951268323875 + 0.000031 - 0.000024
  // m = K (xd, yd, 1) = (519.9830084554925, 430.02651268323875)
  const Vec3d xc = v.pose.R * Vec3d{12, 17, 0} + v.pose.t;
  EXPECT_NEAR(xc.z, 100, 1e-12);
  const LensCamera lens = lens_from_camera(v.camera, v.radial_k3);
  const PinholeCamera ideal{lens.fx, lens.fy, lens.cx, lens.cy, lens.width, lens.height};
  double u, vv;
  distort_pixel(lens, ideal, lens.fx * xc.x / xc.z + lens.cx, lens.fy * xc.y / xc.z + lens.cy, u, vv);
  EXPECT_NEAR(u, 519.9830084554925, 1e-9);
  EXPECT_NEAR(vv, 430.02651268323875, 1e-9);

  const Pix4dView& w = views[1];
  EXPECT_EQ(w.name, "oblique view.jpg");
  EXPECT_EQ(w.camera.model, CameraModel::Pinhole);
  EXPECT_EQ(w.camera.params, (std::vector<double>{800, 810, 320, 240}));
  EXPECT_NEAR(w.pose.t.z, -3, 1e-15);
}

TEST(Pix4d, BadFilesAreErrorsNamingTheFile) {
  std::string text = kCalibration;
  expect_error([&] { parse_pix4d_calibrated_cameras(text.substr(0, text.size() - 8), "c.txt"); },
               {"c.txt", "oblique view.jpg"});
  std::string skew = text;
  skew.replace(skew.find("1000 0 500"), 10, "1000 1 500");
  expect_error([&] { parse_pix4d_calibrated_cameras(skew, "c.txt"); }, {"c.txt", "skew"});
  std::string not_rot = text;
  not_rot.replace(not_rot.find("0 -1 0"), 6, "0 -2 0");
  expect_error([&] { parse_pix4d_calibrated_cameras(not_rot, "c.txt"); }, {"c.txt", "rotation"});
  std::string nan = text;
  nan.replace(nan.find("10 20 100"), 9, "10 nan 100");
  expect_error([&] { parse_pix4d_calibrated_cameras(nan, "c.txt"); }, {"c.txt", "line 15", "nan"});
  expect_error([&] { parse_pix4d_calibrated_cameras("just a header\n", "c.txt"); }, {"c.txt", "no calibrated cameras"});
}

TEST(Pix4d, SceneFromAPix4dProjectUndistortsWithK3) {
  const fs::path dir = test::fresh_dir("pix4d");
  fs::create_directories(dir / "1_initial" / "params");
  // a milder lens than above, so that the 160x120 test image stays invertible
  write_text_atomic(dir / "1_initial" / "params" / "proj_calibrated_camera_parameters.txt",
                    "a.png 160 120\n150 0 81\n0 150 59\n0 0 1\n-0.1 0.02 0.01\n0.001 -0.001\n0 0 0\n"
                    "1 0 0\n0 1 0\n0 0 1\n");
  const auto views = read_pix4d_calibrated_cameras(find_pix4d_calibration(dir.string()));
  fs::create_directories(dir / "images");
  cv::imwrite((dir / "images" / "a.png").string(),
              test::distorted_checkerboard(lens_from_camera(views[0].camera, views[0].radial_k3)));
  const Scene s = load_scene(dir.string());
  EXPECT_EQ(s.source, "pix4d");
  ASSERT_EQ(s.views.size(), 1u);
  EXPECT_EQ(s.views[0].source_radial_k3, 0.01);
  ImageLoader loader;
  EXPECT_GT(test::expect_matches_checkerboard(loader.load(s.views[0]), s.views[0].camera, 3.0, 0), 0.3);

  write_text_atomic(dir / "second_calibrated_camera_parameters.txt", "");
  expect_error([&] { load_scene(dir.string()); }, {"more than one Pix4D calibration file"});
  fs::remove_all(dir);
}
