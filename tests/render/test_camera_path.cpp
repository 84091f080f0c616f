// Camera paths against hand-computed poses.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "raycast/look_at.h"
#include "render/camera_path.h"

namespace cls {
namespace {

constexpr double kPi = 3.14159265358979323846;

Mat3d rot_z(double a) {
  Mat3d R = Mat3d::identity();
  R.m[0][0] = std::cos(a), R.m[0][1] = -std::sin(a);
  R.m[1][0] = std::sin(a), R.m[1][1] = std::cos(a);
  return R;
}

void expect_near(const Mat3d& a, const Mat3d& b, double tol) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tol) << i << "," << j;
}

void expect_near(Vec3d a, Vec3d b, double tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << i;
}

TEST(Orbit, RingOfCamerasGivesTheirCircle) {
  // Four cameras on a circle of radius 10 at height 5 above the target, looking at it, z up.
  const Vec3d target{1, 2, 3};
  std::vector<Pose> cams;
  for (int k = 0; k < 4; ++k) {
    const double a = kPi / 2 * k;
    cams.push_back(look_at(target + Vec3d{10 * std::cos(a), 10 * std::sin(a), 5}, target, {0, 0, 1}));
  }
  const OrbitCircle c = orbit_circle(cams, target);
  expect_near(c.up, {0, 0, 1}, 1e-12);
  EXPECT_NEAR(c.radius, 10, 1e-12);
  EXPECT_NEAR(c.height, 5, 1e-12);
  expect_near(c.start, {1, 0, 0}, 1e-12);  // the first camera's azimuth
  expect_near(c.centre, target + Vec3d{0, 0, 5}, 1e-12);

  const int n = 8;
  const std::vector<Pose> path = orbit_path(c, n);
  ASSERT_EQ(path.size(), size_t(n));
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / n;  // counter-clockwise about +z, starting at +x
    const Vec3d eye = target + Vec3d{10 * std::cos(a), 10 * std::sin(a), 5};
    expect_near(path[k].center(), eye, 1e-9);
    expect_near(path[k].R.row(2), normalized(target - eye), 1e-12);  // looks at the target
    EXPECT_NEAR(path[k].R.row(0).z, 0, 1e-12);                        // no roll: x stays horizontal
    EXPECT_LT(path[k].R.row(1).z, 0);                                 // image y points down
  }
}

TEST(Orbit, MeanRadiusAndHeightOfUnevenCameras) {
  const Vec3d target{0, 0, 0};
  const std::vector<Pose> cams = {look_at({8, 0, 4}, target), look_at({0, 12, 6}, target), look_at({-8, 0, 4}, target),
                                  look_at({0, -12, 6}, target)};
  const OrbitCircle c = orbit_circle(cams, target);
  EXPECT_NEAR(c.radius, 10, 1e-12);
  EXPECT_NEAR(c.height, 5, 1e-12);
  for (const Pose& p : orbit_path(c, 5)) {
    const Vec3d e = p.center();
    EXPECT_NEAR(std::hypot(e.x, e.y), 10, 1e-9);
    EXPECT_NEAR(e.z, 5, 1e-9);
  }
}

TEST(Orbit, BadInputsThrow) {
  EXPECT_THROW(orbit_circle({}, {0, 0, 0}), Error);
  EXPECT_THROW(orbit_circle({look_at({0, 0, 5}, {1, 0, 5})}, {0, 0, 0}), Error);  // on the axis through the target
  const OrbitCircle c = orbit_circle({look_at({3, 0, 1}, {0, 0, 0})}, {0, 0, 0});
  EXPECT_THROW(orbit_path(c, 0), Error);
}

TEST(Slerp, HalfwayAndShorterArc) {
  expect_near(slerp(rot_z(0), rot_z(kPi / 2), 0.5), rot_z(kPi / 4), 1e-12);
  expect_near(slerp(rot_z(0), rot_z(kPi / 2), 0.25), rot_z(kPi / 8), 1e-12);
  expect_near(slerp(rot_z(0.3), rot_z(0.3), 0.7), rot_z(0.3), 1e-12);
  // 170 and -170 degrees meet at 180 degrees, not at 0.
  expect_near(slerp(rot_z(170 * kPi / 180), rot_z(-170 * kPi / 180), 0.5), rot_z(kPi), 1e-12);
}

TEST(Interpolate, PassesThroughKeyframesAndFollowsTheSpline) {
  // Three cameras on the x axis at x = 0, 1, 2, turning about z by 0, 30, 60 degrees.
  std::vector<Pose> keys;
  for (int i = 0; i < 3; ++i) {
    Pose p;
    p.R = rot_z(i * kPi / 6);
    p.t = -(p.R * Vec3d{double(i), 0, 0});
    keys.push_back(p);
  }
  const std::vector<Pose> path = interpolate_path(keys, 5);  // m = 2 frames per segment
  ASSERT_EQ(path.size(), 5u);
  for (int j = 0; j < 3; ++j) {
    expect_near(path[2 * j].R, keys[j].R, 1e-12);
    expect_near(path[2 * j].center(), keys[j].center(), 1e-12);
  }
  // Frame 1: t = 0.5 of segment 0 with the first point repeated: 0.5 (0.5 + 0.25 * 2 - 0.125 * 1) = 0.4375.
  expect_near(path[1].center(), {0.4375, 0, 0}, 1e-12);
  expect_near(path[1].R, rot_z(kPi / 12), 1e-12);
  expect_near(path[3].center(), {2 - 0.4375, 0, 0}, 1e-12);  // mirrored at the other end
  EXPECT_THROW(interpolate_path({keys[0]}, 5), Error);
  EXPECT_THROW(interpolate_path(keys, 1), Error);
}

}  // namespace
}  // namespace cls
