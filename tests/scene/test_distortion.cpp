#include <gtest/gtest.h>

#include <cmath>

#include "scene/distortion.h"
#include "scene/undistort.h"
#include "scene_test_util.h"

using namespace cls;

TEST(Distortion, HandComputedValues) {
  // r2 = 0.13, radial = 0.1 r2 + 0.01 r2^2 + 0.001 r2^3 = 0.013171197
  // xd = 0.3 (1 + radial) + 2 p1 x y + p2 (r2 + 2 x^2) = 0.3 + 0.0039513591 - 0.00012 + 0.00062
  // yd = -0.2 (1 + radial) + p1 (r2 + 2 y^2) + 2 p2 x y = -0.2 - 0.0026342394 + 0.00021 - 0.00024
  const DistortionCoeffs<double> d{0.1, 0.01, 0.001, 0.001, 0.002};
  double xd, yd;
  distort_normalized(d, 0.3, -0.2, xd, yd);
  EXPECT_NEAR(xd, 0.3044513591, 1e-15);
  EXPECT_NEAR(yd, -0.2026642394, 1e-15);
}

TEST(Distortion, ColmapModelsMapToCoefficients) {
  // SIMPLE_RADIAL f=100 c=(50,40) k=-0.1: normalized (0.5, 0) -> 0.5 (1 - 0.1 * 0.25) = 0.4875 -> u = 98.75
  const LensCamera sr = lens_from_camera(Camera{1, CameraModel::SimpleRadial, 100, 80, {100, 50, 40, -0.1}});
  EXPECT_EQ(sr.fx, 100);
  EXPECT_EQ(sr.fy, 100);
  EXPECT_EQ(sr.distortion.k1, -0.1);
  double u, v;
  distort_pixel(sr, PinholeCamera{100, 100, 50, 40, 100, 80}, 100, 40, u, v);
  EXPECT_NEAR(u, 98.75, 1e-12);
  EXPECT_NEAR(v, 40, 1e-12);
  const LensCamera ocv =
      lens_from_camera(Camera{2, CameraModel::OpenCV, 10, 10, {1, 2, 3, 4, 0.1, 0.2, 0.3, 0.4}}, 0.5);
  EXPECT_EQ(ocv.fy, 2);
  EXPECT_EQ(ocv.cy, 4);
  EXPECT_EQ(ocv.distortion.k2, 0.2);
  EXPECT_EQ(ocv.distortion.k3, 0.5);
  EXPECT_EQ(ocv.distortion.p1, 0.3);
  EXPECT_EQ(ocv.distortion.p2, 0.4);
  const LensCamera rad = lens_from_camera(Camera{3, CameraModel::Radial, 10, 10, {7, 3, 4, 0.1, 0.2}});
  EXPECT_EQ(rad.distortion.k2, 0.2);
  EXPECT_TRUE(lens_from_camera(Camera{4, CameraModel::SimplePinhole, 10, 10, {7, 3, 4}}).distortion.is_zero());
}

TEST(Distortion, JacobianMatchesFiniteDifferences) {
  const DistortionCoeffs<double> d{-0.3, 0.12, -0.02, 0.003, -0.004};
  for (double x : {-0.6, -0.1, 0.0, 0.35})
    for (double y : {-0.4, 0.05, 0.5}) {
      double j00, j01, j10, j11, xp, yp, xm, ym;
      distortion_jacobian(d, x, y, j00, j01, j10, j11);
      const double h = 1e-6;
      distort_normalized(d, x + h, y, xp, yp);
      distort_normalized(d, x - h, y, xm, ym);
      EXPECT_NEAR(j00, (xp - xm) / (2 * h), 1e-8);
      EXPECT_NEAR(j10, (yp - ym) / (2 * h), 1e-8);
      distort_normalized(d, x, y + h, xp, yp);
      distort_normalized(d, x, y - h, xm, ym);
      EXPECT_NEAR(j01, (xp - xm) / (2 * h), 1e-8);
      EXPECT_NEAR(j11, (yp - ym) / (2 * h), 1e-8);
    }
}

TEST(Distortion, DistortThenUndistortRoundTrips) {
  const DistortionCoeffs<double> lenses[] = {{-0.1, 0, 0, 0, 0}, {-0.25, 0.07, 0, 0.002, -0.003},
                                             {0.15, -0.05, 0.01, -0.001, 0.001}};
  for (const auto& d : lenses)
    for (double x = -0.7; x <= 0.7; x += 0.05)
      for (double y = -0.5; y <= 0.5; y += 0.05) {
        double xd, yd, xu, yu;
        distort_normalized(d, x, y, xd, yd);
        ASSERT_TRUE(undistort_normalized(d, xd, yd, xu, yu));
        EXPECT_NEAR(xu, x, 1e-12);
        EXPECT_NEAR(yu, y, 1e-12);
      }
  // float instantiation (what a CUDA kernel would use)
  const DistortionCoeffs<float> f{-0.25f, 0.07f, 0.f, 0.002f, -0.003f};
  float xd, yd, xu, yu;
  distort_normalized(f, 0.4f, -0.3f, xd, yd);
  ASSERT_TRUE(undistort_normalized(f, xd, yd, xu, yu));
  EXPECT_NEAR(xu, 0.4f, 1e-5f);
  EXPECT_NEAR(yu, -0.3f, 1e-5f);
}

TEST(Distortion, PixelRoundTripThroughTheUndistortedCamera) {
  const LensCamera lens = lens_from_camera(
      Camera{1, CameraModel::OpenCV, 640, 480, {500, 505, 322, 236, -0.2, 0.05, 0.001, -0.002}}, 0.01);
  const PinholeCamera target = undistorted_pinhole(lens, "test");
  for (double u = 0.5; u < 640; u += 37.5)
    for (double v = 0.5; v < 480; v += 29.5) {
      double tu, tv, u2, v2;
      ASSERT_TRUE(undistort_pixel(lens, target, u, v, tu, tv));
      distort_pixel(lens, target, tu, tv, u2, v2);
      EXPECT_NEAR(u2, u, 1e-9);
      EXPECT_NEAR(v2, v, 1e-9);
    }
}

TEST(UndistortCamera, PinholeIsUnchanged) {
  const LensCamera lens = lens_from_camera(Camera{1, CameraModel::Pinhole, 640, 480, {500, 505, 322, 236}});
  const PinholeCamera p = undistorted_pinhole(lens, "test");
  EXPECT_EQ(p.fx, 500);
  EXPECT_EQ(p.fy, 505);
  EXPECT_EQ(p.cx, 322);
  EXPECT_EQ(p.cy, 236);
  EXPECT_EQ(p.width, 640);
  EXPECT_EQ(p.height, 480);
}

// COLMAP's "no blank pixels" rule: every undistorted pixel centre comes from inside the source
// image, and the new size is tight (some border pixel lands within about a pixel of the source
// border). Focal lengths are kept, the principal point scales with the size.
TEST(UndistortCamera, NoBlankPixelsAndTight) {
  const Camera cams[] = {
      {1, CameraModel::SimpleRadial, 400, 300, {350, 200, 150, -0.15}},                     // barrel: grows
      {2, CameraModel::Radial, 400, 300, {350, 190, 160, 0.12, 0.02}},                      // pincushion: shrinks
      {3, CameraModel::OpenCV, 400, 300, {350, 340, 205, 148, -0.2, 0.04, 0.002, -0.003}},  // tangential too
  };
  for (const Camera& cam : cams) {
    const LensCamera lens = lens_from_camera(cam);
    const PinholeCamera p = undistorted_pinhole(lens, "test");
    EXPECT_EQ(p.fx, lens.fx);
    EXPECT_EQ(p.fy, lens.fy);
    EXPECT_NEAR(p.cx / p.width, lens.cx / lens.width, 1e-12);
    EXPECT_NEAR(p.cy / p.height, lens.cy / lens.height, 1e-12);
    if (cam.id == 1) EXPECT_GT(p.width, cam.width);
    if (cam.id == 2) EXPECT_LT(p.width, cam.width);
    double min_u = 1e9, max_u = -1e9, min_v = 1e9, max_v = -1e9;
    for (int j = 0; j < p.height; ++j)
      for (int i = 0; i < p.width; ++i) {
        if (j != 0 && j != p.height - 1 && i != 0 && i != p.width - 1) continue;  // the border decides
        double u, v;
        distort_pixel(lens, p, i + 0.5, j + 0.5, u, v);
        min_u = std::min(min_u, u);
        max_u = std::max(max_u, u);
        min_v = std::min(min_v, v);
        max_v = std::max(max_v, v);
      }
    EXPECT_GE(min_u, 0.0) << cam.id;
    EXPECT_LE(max_u, double(cam.width)) << cam.id;
    EXPECT_GE(min_v, 0.0) << cam.id;
    EXPECT_LE(max_v, double(cam.height)) << cam.id;
    EXPECT_LT(std::min(min_u, cam.width - max_u), 2.5) << cam.id;
    EXPECT_LT(std::min(min_v, cam.height - max_v), 2.5) << cam.id;
  }
}

TEST(UndistortCamera, HopelessLensIsAnError) {
  // k1 = -3 folds the image at r ~ 0.33, well inside the border: nothing on the border inverts.
  const LensCamera lens = lens_from_camera(Camera{1, CameraModel::SimpleRadial, 400, 300, {100, 200, 150, -3}});
  test::expect_error([&] { undistorted_pinhole(lens, "cams.bin camera 1"); }, {"cams.bin camera 1", "too strong"});
}
