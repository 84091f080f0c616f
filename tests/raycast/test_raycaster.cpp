// Raycaster vs the brute-force oracle (oracle.h) on random triangle soups with coplanar overlays.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/error.h"
#include "raycast/look_at.h"
#include "raycast/raycaster.h"
#include "raycast/oracle.h"

namespace cls {
namespace {

struct Soup {
  std::vector<Vec3f> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint8_t> priority;
  size_t overlays = 0;
};

// Random triangles in a 10 m cube, plus smaller triangles lying exactly in the plane of some of
// them (vertices are convex combinations of the base triangle's) with a higher priority: the
// "window on top of an unholed wall" case, where both are hit at the same depth.
Soup random_soup(uint32_t seed, int base_count, int overlay_count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-5, 5), off(-1.5f, 1.5f), w(0.6f, 0.9f);
  Soup s;
  auto add = [&](Vec3f a, Vec3f b, Vec3f c, uint8_t p) {
    const uint32_t k = static_cast<uint32_t>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), {a, b, c});
    s.triangles.push_back({k, k + 1, k + 2});
    s.priority.push_back(p);
  };
  for (int n = 0; n < base_count; ++n) {
    const Vec3f c{pos(rng), pos(rng), pos(rng)};
    add(c + Vec3f{off(rng), off(rng), off(rng)}, c + Vec3f{off(rng), off(rng), off(rng)},
        c + Vec3f{off(rng), off(rng), off(rng)}, 0);
  }
  // Distinct bases: two overlays on one base would tie at equal priority, which no rule orders.
  std::vector<int> bases(base_count);
  for (int n = 0; n < base_count; ++n) bases[n] = n;
  std::shuffle(bases.begin(), bases.end(), rng);
  for (int n = 0; n < overlay_count; ++n) {
    const auto base = s.triangles[bases[n]];
    const Vec3f a = s.vertices[base[0]], b = s.vertices[base[1]], c = s.vertices[base[2]];
    // Each overlay corner leans towards one base corner, so the overlay covers a good part of it.
    auto near_corner = [&](Vec3f main, Vec3f o1, Vec3f o2) {
      const float m = w(rng), r = 0.5f * (1 - m);
      return m * main + r * o1 + r * o2;
    };
    add(near_corner(a, b, c), near_corner(b, c, a), near_corner(c, a, b), 1);
    ++s.overlays;
  }
  return s;
}

PinholeCamera small_camera() { return {150, 150, 80, 60, 160, 120}; }

TEST(Raycaster, AgreesWithOracleOnRandomSoups) {
  for (uint32_t seed : {1u, 2u, 3u, 4u}) {
    const Soup s = random_soup(seed, 300, 80);
    const Raycaster rc(s.vertices, s.triangles, s.priority);
    ASSERT_EQ(rc.num_triangles(), s.triangles.size());
    std::mt19937 rng(seed + 100);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), elev(-0.8, 0.8);
    for (int view = 0; view < 3; ++view) {
      const double a = angle(rng), e = elev(rng);
      const Vec3d eye{14 * std::cos(a) * std::cos(e), 14 * std::sin(a) * std::cos(e), 14 * std::sin(e)};
      const Pose pose = look_at(eye, {0, 0, 0});
      std::vector<RayHit> hits;
      rc.cast_view(small_camera(), pose, hits);
      const auto truth = test::oracle_view(s.vertices, s.triangles, s.priority, small_camera(), pose);
      ASSERT_EQ(hits.size(), truth.size());
      size_t agree = 0, both_hit = 0, overlay_wins = 0, depth_ok = 0;
      for (size_t p = 0; p < hits.size(); ++p) {
        if (hits[p].prim == truth[p].prim) ++agree;
        if (truth[p].prim != kNoHit && s.priority[truth[p].prim] == 1) ++overlay_wins;
        if (hits[p].prim != kNoHit && hits[p].prim == truth[p].prim) {
          ++both_hit;
          if (std::abs(hits[p].depth - truth[p].depth) <= 1e-4 * truth[p].depth) ++depth_ok;
        }
      }
      SCOPED_TRACE(testing::Message() << "seed " << seed << " view " << view);
      EXPECT_GE(agree, 0.999 * hits.size());
      EXPECT_EQ(depth_ok, both_hit);
      EXPECT_GT(both_hit, hits.size() / 10);  // the soup fills a good part of the frame
      EXPECT_GT(overlay_wins, 50u);           // the tie rule is exercised
    }
  }
}

TEST(Raycaster, OverlayLosesWithoutPriorities) {
  // Same soup, no priorities: the overlays still exist but ties are decided by Embree, so the
  // oracle with priorities disagrees on many overlay pixels. Guards against a test that cannot fail.
  const Soup s = random_soup(7, 300, 80);
  const Raycaster plain(s.vertices, s.triangles);
  const Pose pose = look_at({0, -14, 3}, {0, 0, 0});
  std::vector<RayHit> hits;
  plain.cast_view(small_camera(), pose, hits);
  const auto truth = test::oracle_view(s.vertices, s.triangles, s.priority, small_camera(), pose);
  size_t disagree = 0;
  for (size_t p = 0; p < hits.size(); ++p) disagree += hits[p].prim != truth[p].prim;
  EXPECT_GT(disagree, 0.002 * hits.size());
}

TEST(Raycaster, ArbitraryRaysAgreeWithOracle) {
  const Soup s = random_soup(11, 200, 50);
  const Raycaster rc(s.vertices, s.triangles, s.priority);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<Ray> rays(20000);
  for (auto& r : rays) {
    r.origin = {12 * u(rng), 12 * u(rng), 12 * u(rng)};
    const Vec3f target{4 * u(rng), 4 * u(rng), 4 * u(rng)};
    r.dir = 0.5f * (target - r.origin);  // not unit length: t is in units of |dir|
    r.tnear = 0.5f + 0.5f * u(rng);
  }
  rays[17].tfar = 0.1f;  // a segment too short to reach anything
  std::vector<RayHit> hits;
  rc.cast(rays, hits);
  ASSERT_EQ(hits.size(), rays.size());
  EXPECT_EQ(hits[17].prim, kNoHit);
  size_t agree = 0, hit_count = 0;
  for (size_t k = 0; k < rays.size(); ++k) {
    if (k == 17) continue;
    const auto t = test::oracle_cast(s.vertices, s.triangles, s.priority, cast<double>(rays[k].origin),
                                     cast<double>(rays[k].dir), rays[k].tnear);
    if (t.prim == hits[k].prim) ++agree;
    if (t.prim != kNoHit && t.prim == hits[k].prim) {
      ++hit_count;
      EXPECT_NEAR(hits[k].depth, t.depth, 1e-4 * t.depth);
    }
  }
  EXPECT_GE(agree, 0.999 * (rays.size() - 1));
  EXPECT_GT(hit_count, rays.size() / 4);
}

TEST(Raycaster, DepthIsZDepthAndBarycentricsLocateTheHit) {
  // One big triangle in the plane z = 10 (world), camera at the origin looking down +z:
  // every pixel's z-depth is 10 although the rays are oblique.
  const std::vector<Vec3f> v{{-100, -100, 10}, {100, -100, 10}, {0, 100, 10}};
  const Raycaster rc(v, {{0u, 1u, 2u}});
  const PinholeCamera cam{100, 100, 50, 40, 100, 80};
  std::vector<RayHit> hits;
  rc.cast_view(cam, Pose{}, hits);
  for (int j = 0; j < cam.height; j += 7)
    for (int i = 0; i < cam.width; i += 7) {
      const RayHit& h = hits[static_cast<size_t>(j) * cam.width + i];
      ASSERT_EQ(h.prim, 0u);
      EXPECT_NEAR(h.depth, 10.0f, 1e-5f);
      const Vec3f p = (1 - h.u - h.v) * v[0] + h.u * v[1] + h.v * v[2];
      EXPECT_NEAR(p.x, 10 * (i + 0.5 - cam.cx) / cam.fx, 1e-3);
      EXPECT_NEAR(p.y, 10 * (j + 0.5 - cam.cy) / cam.fy, 1e-3);
    }
}

TEST(Raycaster, HighestPriorityWinsAmongCoplanarLayers) {
  // Three nested coplanar triangles in z = 5: large (priority 0), medium (2), small (1).
  const std::vector<Vec3f> v{{-10, -10, 5}, {10, -10, 5}, {0, 10, 5}, {-5, -5, 5}, {5, -5, 5},
                             {0, 5, 5},     {-2, -2, 5},  {2, -2, 5}, {0, 2, 5}};
  const std::vector<std::array<uint32_t, 3>> tris{{6, 7, 8}, {0, 1, 2}, {3, 4, 5}};  // small, large, medium
  // From 1e5 away the tie tolerance (1e-4 of the depth) exceeds the 1%-of-the-model partner
  // distance, so the far rays exercise the plain gap test instead of the partner boxes.
  for (const float start : {0.0f, -1e5f}) {
    for (const auto& priority : {std::vector<uint8_t>{1, 0, 2}, std::vector<uint8_t>{3, 0, 2}}) {
      const Raycaster rc(v, tris, priority);
      std::vector<Ray> rays(3);
      rays[0].origin = {0, -1, start};   // inside all three
      rays[1].origin = {0, -4, start};   // inside large and medium
      rays[2].origin = {-8, -9, start};  // inside large only
      for (auto& r : rays) r.dir = {0, 0, 1};
      std::vector<RayHit> hits;
      rc.cast(rays, hits);
      EXPECT_EQ(hits[0].prim, priority[0] == 3 ? 0u : 2u);
      EXPECT_EQ(hits[1].prim, 2u);
      EXPECT_EQ(hits[2].prim, 1u);
      for (const auto& h : hits) EXPECT_NEAR(h.depth, 5.0f - start, 1e-6f * (5.0f - start) + 1e-5f);
    }
  }
}

TEST(Raycaster, EmptyMeshHitsNothing) {
  const Raycaster rc({}, {});
  std::vector<RayHit> hits;
  rc.cast_view(small_camera(), Pose{}, hits);
  ASSERT_EQ(hits.size(), 160u * 120u);
  for (const auto& h : hits) ASSERT_EQ(h.prim, kNoHit);
}

TEST(Raycaster, RejectsBadInput) {
  const std::vector<Vec3f> v{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  EXPECT_THROW(Raycaster(v, {{0u, 1u, 3u}}), Error);
  EXPECT_THROW(Raycaster({{0, 0, NAN}, {1, 0, 1}, {0, 1, 1}}, {{0u, 1u, 2u}}), Error);
  EXPECT_THROW(Raycaster(v, {{0u, 1u, 2u}}, {1, 0}), Error);
  const Raycaster rc(v, {{0u, 1u, 2u}});
  std::vector<RayHit> hits;
  EXPECT_THROW(rc.cast_view(PinholeCamera{0, 100, 50, 50, 100, 100}, Pose{}, hits), Error);
}

}  // namespace
}  // namespace cls
