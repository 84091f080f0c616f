#include <gtest/gtest.h>

#include <cmath>

#include "citymodel/mesh_area.h"
#include "citymodel/mesh_builder.h"
#include "core/error.h"

using namespace cls;
using cls::test::total_area;

namespace {

Ring square(double x0, double y0, double size, bool ccw = true) {
  Ring r{{x0, y0, 0}, {x0 + size, y0, 0}, {x0 + size, y0 + size, 0}, {x0, y0 + size, 0}, {x0, y0, 0}};
  if (!ccw) std::reverse(r.begin(), r.end());
  return r;
}

// Rotates about the x axis by `angle` and then translates by `t`: a general 3D plane.
Ring placed(Ring r, double angle, std::array<double, 3> t) {
  for (auto& p : r) {
    const double y = p[1] * std::cos(angle) - p[2] * std::sin(angle);
    const double z = p[1] * std::sin(angle) + p[2] * std::cos(angle);
    p = {p[0] + t[0], y + t[1], z + t[2]};
  }
  return r;
}

// Sum of the triangles' vector areas (orientation-aware).
std::array<double, 3> vector_area(const SemanticMesh& m) {
  std::array<double, 3> s{0, 0, 0};
  for (const auto& t : m.triangles) {
    const auto &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    s[0] += 0.5 * (u[1] * v[2] - u[2] * v[1]);
    s[1] += 0.5 * (u[2] * v[0] - u[0] * v[2]);
    s[2] += 0.5 * (u[0] * v[1] - u[1] * v[0]);
  }
  return s;
}

struct Fixture : ::testing::Test {
  Taxonomy tax = Taxonomy::builtin();
  MeshBuilder builder{tax};
  int wall = tax.find("wall"), window = tax.find("window"), building = tax.find("building");
};

}  // namespace

using MeshBuilderTest = Fixture;

TEST_F(MeshBuilderTest, SquareWithHoleHasExactAreaForEitherHoleOrientation) {
  for (bool hole_ccw : {true, false}) {
    MeshBuilder b(tax);
    ASSERT_TRUE(b.add_polygon({square(0, 0, 10), square(3, 3, 4, hole_ccw)}, wall, -1, "p"));
    const SemanticMesh m = b.finish();
    // 8 ring vertices, 1 hole, no Steiner points: n + 2h - 2 = 8 triangles.
    EXPECT_EQ(m.num_triangles(), 8u);
    EXPECT_DOUBLE_EQ(total_area(m), 100.0 - 16.0);
    const auto va = vector_area(m);  // triangles keep the exterior's orientation (+z)
    EXPECT_DOUBLE_EQ(va[2], 84.0);
  }
}

TEST_F(MeshBuilderTest, TiltedPolygonWithTwoHolesFarFromOrigin) {
  const std::array<double, 3> far{457842.37, 5439083.61, 112.5};
  builder.add_polygon({placed(square(0, 0, 10, false), 1.1, far), placed(square(1, 1, 2), 1.1, far),
                       placed(square(5, 5, 3), 1.1, far)},
                      wall, -1, "tilted");
  const SemanticMesh m = builder.finish();
  EXPECT_NEAR(total_area(m), 100.0 - 4.0 - 9.0, 1e-6);
  // The rotation keeps y and z non-negative, so the bounding box minimum is `far`.
  EXPECT_EQ(m.origin, (std::array<double, 3>{457842.0, 5439083.0, 112.0}));
  for (const auto& v : m.vertices)
    for (double c : v) EXPECT_GE(c, 0.0);
  // Clockwise exterior: the triangles face the same way as the exterior ring.
  const auto va = vector_area(m);
  EXPECT_NEAR(va[2], -87.0 * std::cos(1.1), 1e-6);
}

TEST_F(MeshBuilderTest, NonConvexPolygons) {
  // L shape: 4x4 minus the 2x2 upper right corner.
  builder.add_polygon({{{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {2, 2, 0}, {2, 4, 0}, {0, 4, 0}}}, wall, -1, "L");
  // Comb in the xz plane (a vertical wall): 5 wide, 3 high, two 1x2 notches from the top.
  builder.add_polygon({{{0, 0, 0}, {5, 0, 0}, {5, 0, 3}, {4, 0, 3}, {4, 0, 1}, {3, 0, 1}, {3, 0, 3},
                        {2, 0, 3}, {2, 0, 1}, {1, 0, 1}, {1, 0, 3}, {0, 0, 3}}},
                      wall, -1, "comb");
  const SemanticMesh m = builder.finish();
  EXPECT_EQ(m.num_triangles(), 4u + 10u);  // n - 2 each
  EXPECT_DOUBLE_EQ(total_area(m), 12.0 + (15.0 - 4.0));
}

TEST_F(MeshBuilderTest, SelfIntersectingRingUsesCombineVertex) {
  // Uneven bow tie: edges (0,0)-(3,3) and (3,0)-(0,1) cross at (0.75, 0.75); the loops are
  // triangles of area 3.375 and 0.375 (a symmetric bow tie has a zero Newell normal: degenerate).
  builder.add_polygon({{{0, 0, 0}, {3, 3, 0}, {3, 0, 0}, {0, 1, 0}}}, wall, -1, "bowtie");
  const SemanticMesh m = builder.finish();
  EXPECT_EQ(m.num_triangles(), 2u);
  EXPECT_EQ(m.vertices.size(), 5u);  // 4 ring points + the intersection
  EXPECT_NEAR(total_area(m), 3.75, 1e-12);
}

TEST_F(MeshBuilderTest, DuplicatePolygonIdsAreSkipped) {
  EXPECT_TRUE(builder.add_polygon({square(0, 0, 1)}, wall, -1, "same"));
  EXPECT_FALSE(builder.add_polygon({square(0, 0, 1)}, wall, -1, "same"));
  EXPECT_TRUE(builder.add_polygon({square(0, 0, 1)}, wall, -1, "other"));
  const SemanticMesh m = builder.finish();
  EXPECT_EQ(m.num_triangles(), 4u);
  EXPECT_EQ(m.polygon_ids, (std::vector<std::string>{"same", "other"}));
  EXPECT_EQ(m.tri_polygon, (std::vector<int32_t>{0, 0, 1, 1}));
  // The builder is empty after finish: the id may be added again.
  EXPECT_TRUE(builder.add_polygon({square(0, 0, 1)}, wall, -1, "same"));
}

TEST_F(MeshBuilderTest, DegeneratePolygonsAddNothingAndAreCounted) {
  builder.add_polygon({{{0, 0, 0}, {1, 1, 1}}}, wall, -1, "two points");
  builder.add_polygon({{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0, 0}}}, wall, -1, "collinear");
  builder.add_polygon({{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}}}, wall, -1, "one point");
  builder.add_polygon({}, wall, -1, "no rings");
  builder.add_polygon({square(0, 0, 1), {{0.2, 0.2, 0}, {0.5, 0.5, 0}}}, wall, -1, "two-point hole ignored");
  EXPECT_EQ(builder.degenerate_polygons(), 4u);
  const SemanticMesh m = builder.finish();
  EXPECT_EQ(m.num_triangles(), 2u);
  EXPECT_DOUBLE_EQ(total_area(m), 1.0);
}

TEST_F(MeshBuilderTest, NonFiniteCoordinatesThrow) {
  EXPECT_THROW(builder.add_polygon({{{0, 0, 0}, {1, 0, NAN}, {1, 1, 0}}}, wall, -1, "nan"), Error);
  EXPECT_THROW(builder.add_polygon({{{0, 0, 0}, {INFINITY, 0, 0}, {1, 1, 0}}}, wall, -1, "inf"), Error);
  EXPECT_THROW(builder.add_polygon({{{0, 0, 0}, {1e300, 0, 0}, {1, 1, 0}}}, wall, -1, "huge"), Error);
}

TEST_F(MeshBuilderTest, LevelClassesFollowTheEntityChain) {
  const int roof = tax.find("roof"), surface = tax.find("surface"), door = tax.find("door");
  const int house = builder.add_entity(3, building, -1, "house");
  const int part = builder.add_entity(3, building, house, "part");
  const int w = builder.add_entity(2, wall, part, "wall");
  const int win = builder.add_entity(1, window, w, "window");
  const int lone_door = builder.add_entity(1, door, part, "door without wall");
  const int other = builder.add_entity(3, building, -1, "second house");
  builder.add_polygon({square(0, 0, 1)}, window, win, "window poly");
  builder.add_polygon({square(2, 0, 1)}, wall, w, "wall poly");
  builder.add_polygon({square(4, 0, 1)}, surface, part, "solid poly");  // geometry outside any surface
  builder.add_polygon({square(6, 0, 1)}, roof, other, "roof without entity");
  builder.add_polygon({square(8, 0, 1)}, door, lone_door, "door poly");
  const SemanticMesh m = builder.finish();
  ASSERT_EQ(m.num_triangles(), 10u);
  using L = std::array<int32_t, 3>;
  EXPECT_EQ(m.tri_level_class[0], (L{window, wall, building}));
  EXPECT_EQ(m.tri_entity[0], (L{win, w, house}));  // level 3 = the whole building, not the part
  EXPECT_EQ(m.tri_level_class[2], (L{wall, wall, building}));
  EXPECT_EQ(m.tri_entity[2], (L{-1, w, house}));
  EXPECT_EQ(m.tri_level_class[4], (L{surface, surface, building}));
  EXPECT_EQ(m.tri_level_class[6], (L{roof, roof, building}));
  EXPECT_EQ(m.tri_entity[6], (L{-1, -1, other}));
  EXPECT_EQ(m.tri_level_class[8], (L{door, surface, building}));
  EXPECT_EQ(m.tri_class[0], window);
  EXPECT_EQ(m.tri_class[2], wall);
  EXPECT_EQ(m.buildings, (std::vector<int32_t>{house, other}));
  EXPECT_EQ(m.entities[part].parent, house);
}
