// The synthetic feature provider: determinism and the structure the pipeline relies on.
#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "features/synthetic_provider.h"

namespace cls {
namespace {

// 6 x 5 view: left 3 columns covered: rows 0-1 window (class 0), rows 2-4 wall (class 2);
// level 2 wall everywhere covered, level 3 building (class 11); right 2 columns uncovered.
FeatureView hand_view() {
  FeatureView v;
  v.name = "hand.png";
  v.rgb = cv::Mat(5, 6, CV_8UC3, cv::Scalar(100, 120, 140));
  v.coverage = cv::Mat::zeros(5, 6, CV_8UC1);
  for (auto& l : v.labels) l = cv::Mat::zeros(5, 6, CV_16UC1);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 3; ++x) {
      v.coverage.at<uint8_t>(y, x) = 255;
      v.labels[0].at<uint16_t>(y, x) = y < 2 ? 1 : 3;
      v.labels[1].at<uint16_t>(y, x) = 3;
      v.labels[2].at<uint16_t>(y, x) = 12;
    }
  return v;
}

double cosine(const at::Tensor& a, const std::vector<float>& b) {
  return (a * at::tensor(b)).sum().item<double>() / a.norm().item<double>();
}

TEST(SyntheticProvider, DeterministicFromTheSeed) {
  const Taxonomy tax = Taxonomy::builtin();
  SyntheticProviderParams p;
  SyntheticFeatureProvider a(p, tax), b(p, tax);
  const FeatureView v = hand_view();
  const SamSegments sa = a.sam_segments(v), sb = b.sam_segments(v);
  EXPECT_EQ(sa.seg, sb.seg);
  EXPECT_TRUE(at::equal(sa.features, sb.features));
  EXPECT_TRUE(at::equal(a.text_features({"wall", "a tree"}), b.text_features({"wall", "a tree"})));
  p.seed = 2;
  SyntheticFeatureProvider c(p, tax);
  EXPECT_FALSE(at::equal(c.sam_segments(v).features, sa.features));
  // spec() re-creates the same provider.
  auto d = make_feature_provider(a.spec(), tax);
  EXPECT_TRUE(at::equal(d->sam_segments(v).features, sa.features));
  EXPECT_EQ(d->spec(), a.spec());
}

TEST(SyntheticProvider, SegmentsAreComponentsAndTiles) {
  SyntheticProviderParams p;
  p.tile = 4;
  SyntheticFeatureProvider prov(p, Taxonomy::builtin());
  const FeatureView v = hand_view();
  const SamSegments s = prov.sam_segments(v);
  const int hw = 30;
  ASSERT_EQ(s.seg.size(), 4u * hw);
  // Level s (index 1): window component, wall component, tiles at x = 3 (tile 0/1 for y < 4 / y = 4)
  // and x in 4..5 (tile 1 / 3): tiles of 4 px -> x 3 in tile column 0, x 4-5 in column 1.
  std::set<int32_t> s_ids;
  for (int i = 0; i < hw; ++i) s_ids.insert(s.seg[hw + i]);
  EXPECT_EQ(s_ids.size(), 2u + 4u);  // 2 components + 4 tiles (2 columns x 2 rows)
  EXPECT_EQ(s.seg[hw + 0], s.seg[hw + 1 * 6 + 2]);    // window pixels share a segment
  EXPECT_NE(s.seg[hw + 0], s.seg[hw + 2 * 6 + 0]);    // window vs wall
  // Default repeats s with its own rows, offset by nothing; s is offset by the default's count.
  const int n_default = 6;
  for (int i = 0; i < hw; ++i) EXPECT_EQ(s.seg[hw + i], s.seg[i] + n_default);
  // Level m (index 2): one wall component + 4 tiles; level l: one building + 4 tiles.
  std::set<int32_t> m_ids, l_ids;
  for (int i = 0; i < hw; ++i) m_ids.insert(s.seg[2 * hw + i]), l_ids.insert(s.seg[3 * hw + i]);
  EXPECT_EQ(m_ids.size(), 5u);
  EXPECT_EQ(l_ids.size(), 5u);
  EXPECT_EQ(*m_ids.begin(), 12);
  EXPECT_EQ(*l_ids.begin(), 17);
  EXPECT_EQ(s.features.size(0), 22);
  // Unit rows; the s level's features equal the default's.
  EXPECT_TRUE(at::allclose(s.features.norm(2, 1), at::ones({22}), 1e-5, 1e-5));
  EXPECT_TRUE(at::equal(s.features.slice(0, 0, 6), s.features.slice(0, 6, 12)));
}

TEST(SyntheticProvider, FeaturesPointAtTheirClass) {
  SyntheticProviderParams p;
  p.sam_confusion = 0;
  SyntheticFeatureProvider prov(p, Taxonomy::builtin());
  const FeatureView v = hand_view();
  const SamSegments s = prov.sam_segments(v);
  const int hw = 30;
  const auto window = prov.class_vector(0), wall = prov.class_vector(2), bg = prov.class_vector(-1);
  // Class vectors are nearly orthogonal in 512-d.
  EXPECT_LT(std::abs(cosine(at::tensor(window), wall)), 0.25);
  const at::Tensor f_window = s.features[s.seg[hw + 0]], f_wall = s.features[s.seg[hw + 12]],
                   f_tile = s.features[s.seg[hw + 5]];
  const double expect = 1 / std::sqrt(1 + p.sam_noise * p.sam_noise);  // u + n * e, e ⟂ u on average
  EXPECT_NEAR(cosine(f_window, window), expect, 0.1);
  EXPECT_NEAR(cosine(f_wall, wall), expect, 0.1);
  EXPECT_NEAR(cosine(f_tile, bg), expect, 0.1);
  EXPECT_LT(cosine(f_window, wall), 0.3);

  // Regions: closer to the class (smaller noise).
  RegionMask r;
  r.mask = cv::Mat::ones(5, 6, CV_8UC1);
  r.level = 2;
  r.class_id = 2;
  const at::Tensor g = prov.region_features(v, {r});
  EXPECT_NEAR(cosine(g[0], wall), 1 / std::sqrt(1 + p.gml_noise * p.gml_noise), 0.05);
  r.class_id = -1;
  EXPECT_THROW(prov.region_features(v, {r}), Error);

  // Text: any prompt of a class is close to the class; other text is not.
  const at::Tensor t = prov.text_features({"a wall of a building facade", "facade", "a red bicycle"});
  EXPECT_GT(cosine(t[0], wall), 0.99);
  EXPECT_GT(cosine(t[1], wall), 0.99);
  EXPECT_FALSE(at::equal(t[0], t[1]));  // per-phrase noise
  EXPECT_LT(std::abs(cosine(t[2], wall)), 0.25);
  // A class name that is not among its prompts still names the class.
  const Taxonomy tax = Taxonomy::builtin();
  EXPECT_GT(cosine(prov.text_features({"ground"})[0], prov.class_vector(tax.find("ground"))), 0.99);
}

TEST(SyntheticProvider, ConfusionGivesTheRightFractionOfWrongClasses) {
  // A 64 x 64 view of 16 x 16 separate covered squares (1 px gaps), all "wall" at level 1.
  FeatureView v;
  v.name = "grid.png";
  v.coverage = cv::Mat::zeros(64, 64, CV_8UC1);
  for (auto& l : v.labels) l = cv::Mat::zeros(64, 64, CV_16UC1);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      if (y % 4 != 3 && x % 4 != 3) v.coverage.at<uint8_t>(y, x) = 255, v.labels[0].at<uint16_t>(y, x) = 3;
  SyntheticFeatureProvider prov(SyntheticProviderParams{}, Taxonomy::builtin());
  const SamSegments s = prov.sam_segments(v);
  const auto wall = prov.class_vector(2);
  int segments = 0, wrong = 0;
  std::set<int32_t> seen;
  for (int y = 0; y < 64; y += 4)
    for (int x = 0; x < 64; x += 4) {
      const int32_t id = s.seg[64 * 64 + y * 64 + x];
      ASSERT_GE(id, 0);
      if (!seen.insert(id).second) continue;
      ++segments;
      wrong += cosine(s.features[id], wall) < 0.5;
    }
  EXPECT_EQ(segments, 256);
  EXPECT_NEAR(wrong / 256.0, 0.2, 0.07);
}

TEST(SyntheticProvider, BadSpecsAreErrors) {
  const Taxonomy tax = Taxonomy::builtin();
  EXPECT_THROW(make_feature_provider({{"provider", "synthetic"}, {"noise", 1}}, tax), Error);
  EXPECT_THROW(make_feature_provider({{"provider", "synthetic"}, {"dim", "big"}}, tax), Error);
  EXPECT_THROW(make_feature_provider({{"provider", "synthetic"}, {"sam_confusion", 2}}, tax), Error);
  EXPECT_THROW(make_feature_provider({{"provider", "magic"}}, tax), UsageError);
  EXPECT_THROW(make_feature_provider(nlohmann::json::object(), tax), UsageError);
}

}  // namespace
}  // namespace cls
