// CityGML regions R^{l,c} = (C^l == c and M == 1) on hand-made 6 x 5 label maps, and the fusion.
#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "features/city_regions.h"

namespace cls {
namespace {

// Level 1 (values = class + 1, 0 = none):       building (index + 1):   coverage (1 = M):
//   1 1 0 1 1 3                                   1 1 1 2 2 2             1 1 1 1 1 0
//   1 1 0 1 1 3                                   1 1 1 2 2 2             1 1 1 1 1 0
//   3 3 3 3 3 3                                   1 1 1 2 2 2             1 1 1 1 1 0
//   3 3 3 3 3 3                                   1 1 1 2 2 2             1 1 1 1 1 1
//   0 0 0 0 0 0                                   0 0 0 0 0 0             0 0 0 0 0 0
// Window (class 0) in two blocks, one per building; wall (class 2) elsewhere; column 5 is wall
// at level 1 but uncovered in rows 0-2 (so it must not count); row 4 is unlabelled.
// Level 2: wall wherever level 1 is labelled; level 3: building (class 11) the same.
struct HandMaps {
  std::array<cv::Mat, 3> labels;
  cv::Mat coverage, building;
};

HandMaps hand_maps() {
  const int l1[5][6] = {{1, 1, 0, 1, 1, 3}, {1, 1, 0, 1, 1, 3}, {3, 3, 3, 3, 3, 3}, {3, 3, 3, 3, 3, 3}, {0, 0, 0, 0, 0, 0}};
  HandMaps m;
  for (auto& l : m.labels) l = cv::Mat::zeros(5, 6, CV_16UC1);
  m.coverage = cv::Mat::zeros(5, 6, CV_8UC1);
  m.building = cv::Mat::zeros(5, 6, CV_16UC1);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) {
      m.labels[0].at<uint16_t>(y, x) = l1[y][x];
      const bool labelled = y < 4 && !(l1[y][x] == 0);
      m.labels[1].at<uint16_t>(y, x) = labelled ? 3 : 0;
      m.labels[2].at<uint16_t>(y, x) = labelled ? 12 : 0;
      m.coverage.at<uint8_t>(y, x) = (y < 4 && x < 5) || (y == 3) ? 255 : 0;
      m.building.at<uint16_t>(y, x) = y < 4 ? (x < 3 ? 1 : 2) : 0;
    }
  return m;
}

int32_t at(const CityRegionSet& s, int level, int y, int x) { return s.seg[(size_t(level - 1) * 5 + y) * 6 + x]; }

TEST(CityRegions, ClassModeOneRegionPerLevelAndClass) {
  const HandMaps m = hand_maps();
  const CityRegionSet s = extract_city_regions(m.labels, m.coverage, m.building, RegionMode::Class,
                                               Taxonomy::builtin(), 1, "hand");
  // Level 1: window (8 px), wall (covered: rows 2-3 x 0-4 = 10, plus (3, 5) = 11); level 2: wall
  // (8 + 11 = 19); level 3: building (19).
  ASSERT_EQ(s.regions.size(), 4u);
  EXPECT_EQ(s.regions[0].class_name, "window");
  EXPECT_EQ(s.regions[0].pixels, 8);
  EXPECT_EQ(s.regions[1].class_name, "wall");
  EXPECT_EQ(s.regions[1].pixels, 11);
  EXPECT_EQ(s.regions[2].level, 2);
  EXPECT_EQ(s.regions[2].pixels, 19);
  EXPECT_EQ(s.regions[3].class_name, "building");
  EXPECT_EQ(s.regions[3].level, 3);
  for (const auto& r : s.regions) EXPECT_EQ(r.instance, -1);
  // Seg map: ids where C^l == c and M == 1, -1 elsewhere.
  EXPECT_EQ(at(s, 1, 0, 0), 0);
  EXPECT_EQ(at(s, 1, 0, 4), 0);
  EXPECT_EQ(at(s, 1, 0, 2), -1);  // unlabelled
  EXPECT_EQ(at(s, 1, 0, 5), -1);  // wall but uncovered
  EXPECT_EQ(at(s, 1, 3, 5), 1);   // wall and covered
  EXPECT_EQ(at(s, 1, 4, 0), -1);
  EXPECT_EQ(at(s, 2, 0, 0), 2);
  EXPECT_EQ(at(s, 3, 2, 2), 3);
  // Masks agree with the seg map.
  for (size_t r = 0; r < s.masks.size(); ++r) {
    EXPECT_EQ(cv::countNonZero(s.masks[r].mask), s.regions[r].pixels);
    EXPECT_EQ(s.masks[r].class_id, s.regions[r].class_id);
    EXPECT_EQ(s.masks[r].level, s.regions[r].level);
  }
}

TEST(CityRegions, InstanceModeOneRegionPerComponentWithinABuilding) {
  const HandMaps m = hand_maps();
  const CityRegionSet s = extract_city_regions(m.labels, m.coverage, m.building, RegionMode::Instance,
                                               Taxonomy::builtin(), 1, "hand");
  // Level 1: window in building 0 (4 px), window in building 1 (4 px), wall in building 0
  // (rows 2-3 x 0-2 = 6 px), wall in building 1 (rows 2-3 x 3-4 + (3, 5) = 5 px). Level 2: wall
  // per building (6 + 4 = 10, 5 + 4 = 9 px); level 3: building per building (10, 9).
  ASSERT_EQ(s.regions.size(), 8u);
  EXPECT_EQ(s.regions[0].class_name, "window");
  EXPECT_EQ(s.regions[0].building, 0);
  EXPECT_EQ(s.regions[0].instance, 0);
  EXPECT_EQ(s.regions[0].pixels, 4);
  EXPECT_EQ(s.regions[1].building, 1);
  EXPECT_EQ(s.regions[1].instance, 1);
  EXPECT_EQ(s.regions[2].class_name, "wall");
  EXPECT_EQ(s.regions[2].pixels, 6);
  EXPECT_EQ(s.regions[3].pixels, 5);
  EXPECT_EQ(s.regions[4].pixels, 10);
  EXPECT_EQ(s.regions[5].pixels, 9);
  EXPECT_EQ(s.regions[6].class_name, "building");
  EXPECT_EQ(s.regions[6].building, 0);
  EXPECT_EQ(s.regions[7].building, 1);
  EXPECT_EQ(at(s, 1, 0, 0), 0);
  EXPECT_EQ(at(s, 1, 0, 3), 1);
  EXPECT_EQ(at(s, 3, 0, 0), 6);
  EXPECT_EQ(at(s, 3, 0, 4), 7);

  // Two separate windows within one building are two instances.
  HandMaps one = m;
  one.building.setTo(1, one.building > 0);
  const CityRegionSet t = extract_city_regions(one.labels, one.coverage, one.building, RegionMode::Instance,
                                               Taxonomy::builtin(), 1, "hand");
  EXPECT_EQ(t.regions[0].class_name, "window");
  EXPECT_EQ(t.regions[1].class_name, "window");
  EXPECT_EQ(t.regions[1].instance, 1);
  EXPECT_EQ(t.regions[1].building, 0);
  EXPECT_EQ(t.regions[2].class_name, "wall");  // the wall is one connected component
}

TEST(CityRegions, SmallRegionsAreSkipped) {
  const HandMaps m = hand_maps();
  const CityRegionSet s = extract_city_regions(m.labels, m.coverage, m.building, RegionMode::Instance,
                                               Taxonomy::builtin(), 5, "hand");
  // The 4-px windows go; their pixels stay -1.
  for (const auto& r : s.regions) EXPECT_GE(r.pixels, 5);
  EXPECT_EQ(s.regions.size(), 6u);
  EXPECT_EQ(at(s, 1, 0, 0), -1);
  EXPECT_EQ(at(s, 1, 2, 0), 0);
}

TEST(CityRegions, BadMapsAreErrors) {
  HandMaps m = hand_maps();
  m.labels[0].at<uint16_t>(0, 0) = 99;
  EXPECT_THROW(extract_city_regions(m.labels, m.coverage, m.building, RegionMode::Class, Taxonomy::builtin(), 1, "x"),
               Error);
  m = hand_maps();
  EXPECT_THROW(extract_city_regions(m.labels, m.coverage, cv::Mat(), RegionMode::Instance, Taxonomy::builtin(), 1, "x"),
               Error);
  m.coverage = cv::Mat::zeros(4, 6, CV_8UC1);
  EXPECT_THROW(extract_city_regions(m.labels, m.coverage, m.building, RegionMode::Class, Taxonomy::builtin(), 1, "x"),
               Error);
}

TEST(Fusion, MatchesTheFormulaByHand) {
  // gml = (1, 0, 0), txt = (0, 1, 0): (1 - a) gml + a txt = (0.75, 0.25, 0) at a = 0.25, normalised
  // (0.75, 0.25) / sqrt(0.625).
  const at::Tensor gml = at::tensor({1.f, 0.f, 0.f, 0.6f, 0.8f, 0.f}).reshape({2, 3});
  const at::Tensor txt = at::tensor({0.f, 1.f, 0.f, 0.6f, 0.8f, 0.f}).reshape({2, 3});
  const at::Tensor f = fuse_features(gml, txt, 0.25);
  const double n = std::sqrt(0.75 * 0.75 + 0.25 * 0.25);
  EXPECT_NEAR(f[0][0].item<double>(), 0.75 / n, 1e-6);
  EXPECT_NEAR(f[0][1].item<double>(), 0.25 / n, 1e-6);
  EXPECT_NEAR(f[0][2].item<double>(), 0.0, 1e-6);
  EXPECT_NEAR(f[1][0].item<double>(), 0.6, 1e-6);  // equal inputs stay put
  EXPECT_TRUE(at::allclose(fuse_features(gml, txt, 0.0), gml));
  EXPECT_TRUE(at::allclose(fuse_features(gml, txt, 1.0), txt));
  // Opposite directions at alpha 0.5: zero, not NaN.
  const at::Tensor z = fuse_features(gml.slice(0, 0, 1), -gml.slice(0, 0, 1), 0.5);
  EXPECT_EQ(z.abs().sum().item<double>(), 0.0);
  EXPECT_THROW(fuse_features(gml, txt, 1.5), Error);
}

}  // namespace
}  // namespace cls
