// Point-to-mesh distances (align-check): exact hand-made cases and a brute-force comparison.
#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "raycast/alignment.h"
#include "raycast/closest_point.h"

namespace cls {
namespace {

// The unit square x, y in [0, 1] at z = 0 as two triangles.
const std::vector<Vec3f> kSquare{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<std::array<uint32_t, 3>> kSquareTris{{0, 1, 2}, {0, 2, 3}};

TEST(ClosestPoint, ExactDistancesToASquare) {
  const ClosestPointQuery q(kSquare, kSquareTris);
  EXPECT_DOUBLE_EQ(q.distance({0.5, 0.5, 2}), 2);           // above the face
  EXPECT_DOUBLE_EQ(q.distance({0.3, 0.2, -0.5}), 0.5);      // below the face
  EXPECT_DOUBLE_EQ(q.distance({2, 0.5, 0}), 1);             // beside an edge
  EXPECT_DOUBLE_EQ(q.distance({2, 2, 0}), std::sqrt(2.0));  // off a corner
  EXPECT_DOUBLE_EQ(q.distance({1.5, 0.5, 1}), std::sqrt(1.25));
  EXPECT_DOUBLE_EQ(q.distance({0.25, 0.75, 0}), 0);         // on the face
  const auto all = q.distances({{0.5, 0.5, 2}, {2, 0.5, 0}});
  EXPECT_EQ(all, (std::vector<double>{2, 1}));
}

TEST(ClosestPoint, NearestPointTriangleNormalAndWhetherItIsOnAFace) {
  const ClosestPointQuery q(kSquare, kSquareTris);
  const MeshPoint above = q.nearest({0.75, 0.25, 2});  // over triangle 0 (below the diagonal x = y)
  EXPECT_EQ(above.triangle, 0u);
  EXPECT_TRUE(above.on_face);
  EXPECT_DOUBLE_EQ(above.point.x, 0.75);
  EXPECT_DOUBLE_EQ(above.point.y, 0.25);
  EXPECT_DOUBLE_EQ(above.point.z, 0);
  EXPECT_DOUBLE_EQ(above.normal.z, 1);  // counter-clockwise seen from +z
  EXPECT_TRUE(q.nearest({0.5, 0.5, -1}).on_face);   // over the shared diagonal: still a face point
  EXPECT_FALSE(q.nearest({2, 0.5, 0.1}).on_face);   // beside the square's edge
  EXPECT_FALSE(q.nearest({-1, -1, 0}).on_face);     // off a corner
  EXPECT_DOUBLE_EQ(q.nearest({2, 0.5, 0.1}).point.x, 1);
}

TEST(ClosestPoint, EmptyMeshIsInfinitelyFar) {
  const ClosestPointQuery q({}, {});
  EXPECT_EQ(q.distance({0, 0, 0}), INFINITY);
}

TEST(ClosestPoint, RejectsBadMesh) {
  EXPECT_THROW(ClosestPointQuery(kSquare, {{0u, 1u, 9u}}), Error);
}

// Independent formula: the plane distance if the projection falls inside, else the nearest edge.
double brute_distance(Vec3d p, Vec3d a, Vec3d b, Vec3d c) {
  auto segment = [&](Vec3d s, Vec3d e) {
    const Vec3d d = e - s;
    const double t = std::clamp(dot(p - s, d) / dot(d, d), 0.0, 1.0);
    return norm(s + t * d - p);
  };
  const Vec3d n = normalized(cross(b - a, c - a));
  const Vec3d proj = p - dot(p - a, n) * n;
  const bool inside = dot(cross(b - a, proj - a), n) >= 0 && dot(cross(c - b, proj - b), n) >= 0 &&
                      dot(cross(a - c, proj - c), n) >= 0;
  if (inside) return std::abs(dot(p - a, n));
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

TEST(ClosestPoint, AgreesWithBruteForceOnRandomSoup) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-10, 10), off(-2, 2);
  std::vector<Vec3f> v;
  std::vector<std::array<uint32_t, 3>> tris;
  for (uint32_t k = 0; k < 400; ++k) {
    const Vec3f c{u(rng), u(rng), u(rng)};
    for (int n = 0; n < 3; ++n) v.push_back(c + Vec3f{off(rng), off(rng), off(rng)});
    tris.push_back({3 * k, 3 * k + 1, 3 * k + 2});
  }
  const ClosestPointQuery q(v, tris);
  std::vector<Vec3d> points;
  for (int k = 0; k < 2000; ++k) points.push_back({1.3 * u(rng), 1.3 * u(rng), 1.3 * u(rng)});
  const auto got = q.distances(points);
  for (size_t k = 0; k < points.size(); ++k) {
    double best = INFINITY;
    for (const auto& t : tris)
      best = std::min(best, brute_distance(points[k], cast<double>(v[t[0]]), cast<double>(v[t[1]]),
                                           cast<double>(v[t[2]])));
    ASSERT_NEAR(got[k], best, 1e-9 + 1e-9 * best) << "point " << k;
  }
}

TEST(Alignment, StatisticsOfKnownDistances) {
  const AlignmentStats s = alignment_stats({0.1, 0.7, 0.2, 3.0}, 0.5);
  EXPECT_EQ(s.points, 4u);
  EXPECT_DOUBLE_EQ(s.fraction_within, 0.5);
  EXPECT_DOUBLE_EQ(s.median, 0.45);
  EXPECT_DOUBLE_EQ(s.mean, 1.0);
  const AlignmentStats odd = alignment_stats({5, 1, 3}, 3);
  EXPECT_DOUBLE_EQ(odd.median, 3);
  EXPECT_DOUBLE_EQ(odd.fraction_within, 2.0 / 3);
  EXPECT_THROW(alignment_stats({}, 1), Error);
}

}  // namespace
}  // namespace cls
