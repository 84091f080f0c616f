// Point-to-plane ICP (align): known similarities recovered on random meshes with outliers, the
// similarity algebra it relies on checked against independent formulas.
#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "raycast/alignment.h"
#include "raycast/point_to_plane_icp.h"
#include "synth/city_error.h"

namespace cls {
namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

// A random "district": boxes of random size and heading standing on z = 0 (walls and a roof each,
// no floor), like LoD2 buildings.
void random_boxes(std::mt19937& rng, int count, std::vector<Vec3f>& v, Triangles& tris) {
  std::uniform_real_distribution<double> pos(-15, 15), size(4, 12), height(5, 15), heading(0, M_PI);
  for (int b = 0; b < count; ++b) {
    const Vec3d c{pos(rng), pos(rng), 0};
    const double hx = size(rng) / 2, hy = size(rng) / 2, h = height(rng), a = heading(rng);
    const uint32_t base = v.size();
    for (int k = 0; k < 8; ++k) {
      const double x = (k & 1 ? hx : -hx), y = (k & 2 ? hy : -hy), z = (k & 4 ? h : 0);
      v.push_back(cast<float>(c + Vec3d{x * std::cos(a) - y * std::sin(a), x * std::sin(a) + y * std::cos(a), z}));
    }
    // Four walls and the roof as quads of corner indices.
    for (const auto& q : {std::array<uint32_t, 4>{0, 1, 5, 4}, {1, 3, 7, 5}, {3, 2, 6, 7}, {2, 0, 4, 6}, {4, 5, 7, 6}}) {
      tris.push_back({base + q[0], base + q[1], base + q[2]});
      tris.push_back({base + q[0], base + q[2], base + q[3]});
    }
  }
}

// Area-weighted samples on the triangles with Gaussian noise.
std::vector<Vec3d> surface_samples(std::mt19937& rng, const std::vector<Vec3f>& v, const Triangles& tris, int count,
                                   double noise) {
  std::vector<double> areas;
  for (const auto& t : tris) {
    const Vec3d a = cast<double>(v[t[0]]);
    areas.push_back(0.5 * norm(cross(cast<double>(v[t[1]]) - a, cast<double>(v[t[2]]) - a)));
  }
  std::discrete_distribution<size_t> pick(areas.begin(), areas.end());
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> jitter(0, noise);
  std::vector<Vec3d> out;
  for (int k = 0; k < count; ++k) {
    const auto& t = tris[pick(rng)];
    double r1 = u(rng), r2 = u(rng);
    if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
    const Vec3d a = cast<double>(v[t[0]]);
    const Vec3d p = a + r1 * (cast<double>(v[t[1]]) - a) + r2 * (cast<double>(v[t[2]]) - a);
    out.push_back(p + Vec3d{jitter(rng), jitter(rng), jitter(rng)});
  }
  return out;
}

// Terrain around the buildings and "trees and cars": what the city model lacks.
void add_outliers(std::mt19937& rng, int terrain, int clutter, std::vector<Vec3d>& points) {
  std::uniform_real_distribution<double> xy(-30, 30), z(0, 6);
  std::normal_distribution<double> ground(0, 0.02);
  for (int k = 0; k < terrain; ++k) points.push_back({xy(rng), xy(rng), ground(rng)});
  for (int k = 0; k < clutter; ++k) points.push_back({xy(rng), xy(rng), z(rng)});
}

TEST(SimilarityAlgebra, RodriguesAgreesWithTheQuaternionFormula) {
  const Vec3d axis = normalized(Vec3d{0.3, -0.5, 0.8});
  const double angle = 0.7;
  const Mat3d a = axis_angle_to_rotation(angle * axis);
  const Mat3d b = quat_to_rotation(std::cos(angle / 2), std::sin(angle / 2) * axis.x, std::sin(angle / 2) * axis.y,
                                   std::sin(angle / 2) * axis.z);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], 1e-15);
  EXPECT_NEAR(rotation_angle(a), angle, 1e-15);
  EXPECT_NEAR(rotation_angle(axis_angle_to_rotation(Vec3d{0, 0, 1e-7})), 1e-7, 1e-20);  // small angles stay exact
}

TEST(SimilarityAlgebra, InverseAndCompositionOnAHandCase) {
  // x -> 2 Rz(90) x + (1, 2, 3): (1, 0, 0) -> (1, 4, 3).
  const CityTransform t = similarity_transform(2, axis_angle_to_rotation(Vec3d{0, 0, M_PI / 2}), {1, 2, 3});
  const Vec3d y = t.apply({1, 0, 0});
  EXPECT_NEAR(y.x, 1, 1e-15);
  EXPECT_NEAR(y.y, 4, 1e-15);
  EXPECT_NEAR(y.z, 3, 1e-15);
  const Vec3d back = inverse(t).apply(y);
  EXPECT_NEAR(back.x, 1, 1e-15);
  EXPECT_NEAR(back.y, 0, 1e-15);
  const CityTransform twice = t * t;  // 4 Rz(180) x + 2 Rz(90) (1, 2, 3) + (1, 2, 3) = (4 Rz(180) x) + (-3, 4, 9)
  const Vec3d z = twice.apply({1, 0, 0});
  EXPECT_NEAR(z.x, -7, 1e-14);
  EXPECT_NEAR(z.y, 4, 1e-14);
  EXPECT_NEAR(z.z, 9, 1e-14);
  EXPECT_DOUBLE_EQ(twice.scale(), 4);
}

TEST(SimilarityAlgebra, TransformDifferenceOfAKnownShift) {
  SemanticMesh mesh;
  mesh.origin = {100, 0, 0};
  mesh.vertices = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
  const CityTransform b = similarity_transform(2, Mat3d::identity(), {0, 0, 0});
  // a: b, then 1 degree about z through the scene origin and 0.5% larger.
  const CityTransform a =
      similarity_transform(1.005, axis_angle_to_rotation(Vec3d{0, 0, M_PI / 180}), {0, 0, 0}) * b;
  const TransformDifference d = transform_difference(a, b, mesh);
  EXPECT_NEAR(d.rotation_deg, 1, 1e-12);
  EXPECT_NEAR(d.scale, 0.005, 1e-12);
  // Vertex (110, 0, 0): scene (220, 0, 0) moves to 1.005 * 220 (cos 1deg, sin 1deg); in model units / 2.
  const Vec3d moved = 1.005 * 220 * Vec3d{std::cos(M_PI / 180), std::sin(M_PI / 180), 0};
  EXPECT_NEAR(d.max_displacement, norm(moved - Vec3d{220, 0, 0}) / 2, 1e-9);
}

struct Case {
  uint32_t seed;
  bool rigid;
};

class IcpRecovers : public ::testing::TestWithParam<Case> {};

// The goal: from 1 m, 2 deg and 1% off, within 3 cm and 0.05 deg, with half as many points
// again on terrain and clutter as on the buildings.
TEST_P(IcpRecovers, AKnownSimilarityDespiteOutliers) {
  const Case c = GetParam();
  std::mt19937 rng(c.seed);
  std::vector<Vec3f> v;
  Triangles tris;
  random_boxes(rng, 3, v, tris);
  std::vector<Vec3d> points = surface_samples(rng, v, tris, 6000, 0.01);
  add_outliers(rng, 2000, 1000, points);
  const CityTransform truth = synth::city_error_transform({1.0, 2.0, c.rigid ? 0.0 : 0.01}, c.seed, {0, 0, 5});
  // The points the scene gives are where the truth's inverse puts them; ICP must find `truth`.
  std::vector<Vec3d> scene = points;
  for (auto& p : scene) p = inverse(truth).apply(p);
  IcpOptions options;
  options.rigid = c.rigid;
  const ClosestPointQuery mesh(v, tris);
  const IcpResult r = point_to_plane_icp(mesh, scene, options);

  SemanticMesh sm;
  for (const auto& x : v) sm.vertices.push_back({x.x, x.y, x.z});
  const TransformDifference d = transform_difference(r.motion, truth, sm);
  EXPECT_LT(d.max_displacement, 0.03) << "centre " << d.centre << " rotation " << d.rotation_deg;
  EXPECT_LT(d.rotation_deg, 0.05);
  EXPECT_LT(std::fabs(d.scale), 0.001);
  if (c.rigid) EXPECT_NEAR(r.motion.scale(), 1, 1e-12);
  EXPECT_GT(r.conditioning, 1e-4);
  ASSERT_FALSE(r.stages.empty());
  EXPECT_DOUBLE_EQ(r.stages.front().gate, options.capture);
  EXPECT_FALSE(r.stages.front().scale);
  EXPECT_DOUBLE_EQ(r.stages.back().gate, options.finest);
  EXPECT_EQ(r.stages.back().scale, !c.rigid);
  EXPECT_LT(r.stages.back().rms, 0.03);  // the noise is 1 cm per axis
}

INSTANTIATE_TEST_SUITE_P(RandomDistricts, IcpRecovers,
                         ::testing::Values(Case{1, false}, Case{2, false}, Case{3, false}, Case{4, true}, Case{5, true}),
                         [](const auto& info) {
                           return std::string(info.param.rigid ? "rigid" : "similarity") + "_seed" +
                                  std::to_string(info.param.seed);
                         });

TEST(Icp, ScheduleIsRigidCoarseToFineThenWithScale) {
  IcpOptions o;
  o.capture = 2;
  o.finest = 0.1;
  std::vector<std::pair<double, bool>> got;
  for (const auto& s : icp_schedule(o)) got.push_back({s.gate, s.scale});
  const std::vector<std::pair<double, bool>> want{{2, false},    {1, false},   {0.5, false}, {0.25, false}, {0.125, false},
                                                  {0.1, false},  {0.4, true},  {0.2, true},  {0.1, true}};
  EXPECT_EQ(got, want);
  o.rigid = true;
  EXPECT_EQ(icp_schedule(o).size(), 6u);
}

TEST(Icp, OnePlaneLeavesItsInPlaneMotionsAloneAndSaysSo) {
  std::vector<Vec3f> v{{-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}};
  const Triangles tris{{0, 1, 2}, {0, 2, 3}};
  std::vector<Vec3d> points;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) points.push_back({i - 9.5, j - 9.5, 0.3});
  const IcpResult r = point_to_plane_icp(ClosestPointQuery(v, tris), points, {});
  EXPECT_LT(r.conditioning, 1e-9);
  for (const auto& p : points) EXPECT_NEAR(r.motion.apply(p).z, 0, 1e-6);  // the offset along the normal is found
  const Vec3d c = r.motion.apply({0.5, 0.5, 0.3});                         // and nothing moves sideways
  EXPECT_NEAR(c.x, 0.5, 1e-6);
  EXPECT_NEAR(c.y, 0.5, 1e-6);
}

TEST(Icp, FailsClearlyWhenThePointsAreOutOfReach) {
  std::vector<Vec3f> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<Vec3d> points(50, Vec3d{0.2, 0.2, 10});
  try {
    point_to_plane_icp(ClosestPointQuery(v, {{0u, 1u, 2u}}), points, {});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("0 of 50 points lie within 2"), std::string::npos) << e.what();
  }
  IcpOptions bad;
  bad.finest = 3;  // above the capture distance
  EXPECT_THROW(point_to_plane_icp(ClosestPointQuery(v, {{0u, 1u, 2u}}), points, bad), Error);
}

}  // namespace
}  // namespace cls
