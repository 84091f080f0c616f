// The answer as city objects (query/object_ranking.h) on a hand-made table whose every figure is
// computed by hand below.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "query/object_ranking.h"

namespace cls {
namespace {

// Building 0 with wall 1 (windows 2 and 3 on it) and roof 4.
CityObjects hand_table() {
  CityObjects t;
  t.class_names = {"window", "wall", "roof", "building"};
  t.objects = {{"B", 3, 3, -1}, {"W", 2, 1, 0}, {"A", 1, 0, 1}, {"win,\"C\"", 1, 0, 1}, {"R", 2, 2, 0}};
  return t;
}

struct HandGaussians {
  std::vector<int32_t> object{2, 2, 2, 3, 3, 3, 1, 1, 1, 4, 4, 4, -1, 2};
  std::vector<float> scores{0.9f, 0.8f, 0.7f, 0.95f, 0.85f, 0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.5f, 0.5f, 1.0f, 0.6f};
  std::vector<float> means;
  HandGaussians() {
    // Window A's Gaussians (0, 1, 2, 13) at x = 0, 2, 4, 6: centre (3, 0, 0), radius 3.
    const float ax[14] = {0, 2, 4, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 6};
    for (int i = 0; i < 14; ++i) means.insert(means.end(), {ax[i], 0.0f, 0.0f});
  }
  std::vector<ObjectScore> rank(int level, int64_t min_gaussians = 3) const {
    ObjectRankingOptions o;
    o.level = level;
    o.threshold = 0.65;
    o.min_gaussians = min_gaussians;
    return rank_objects(hand_table(), object.data(), scores.data(), means.data(), 14, o);
  }
};

TEST(ObjectRanking, MeanScoresPerObjectAtEachLevel) {
  const HandGaussians h;
  // Level 1: A (0.9 + 0.8 + 0.7 + 0.6) / 4 = 0.75, C 1.9 / 3, roof 0.5, the wall's own Gaussians 0.3.
  const auto l1 = h.rank(1);
  ASSERT_EQ(l1.size(), 4u);
  EXPECT_EQ(l1[0].object, 2);
  EXPECT_NEAR(l1[0].mean_score, 0.75, 1e-6);
  EXPECT_NEAR(l1[0].max_score, 0.9, 1e-6);
  EXPECT_NEAR(l1[0].above, 0.75, 1e-12);  // 3 of 4 >= 0.65
  EXPECT_EQ(l1[0].gaussians, 4);
  EXPECT_NEAR(l1[0].center[0], 3.0, 1e-6);
  EXPECT_NEAR(l1[0].radius, 3.0, 1e-6);
  EXPECT_EQ(l1[1].object, 3);
  EXPECT_NEAR(l1[1].mean_score, 1.9 / 3, 1e-6);
  EXPECT_NEAR(l1[1].above, 2.0 / 3, 1e-12);
  EXPECT_EQ(l1[2].object, 4);
  EXPECT_EQ(l1[3].object, 1);
  EXPECT_NEAR(l1[3].mean_score, 0.3, 1e-6);
  // Level 2: the wall with its windows (5.8 / 10 = 0.58) before the roof (0.5).
  const auto l2 = h.rank(2);
  ASSERT_EQ(l2.size(), 2u);
  EXPECT_EQ(l2[0].object, 1);
  EXPECT_EQ(l2[0].gaussians, 10);
  EXPECT_NEAR(l2[0].mean_score, 0.58, 1e-6);
  EXPECT_EQ(l2[1].object, 4);
  // Level 3: the building, every Gaussian with an object (7.3 / 13); the one without is nobody's.
  const auto l3 = h.rank(3);
  ASSERT_EQ(l3.size(), 1u);
  EXPECT_EQ(l3[0].gaussians, 13);
  EXPECT_NEAR(l3[0].mean_score, 7.3 / 13, 1e-6);
  // Objects with fewer Gaussians than the minimum are not ranked.
  const auto strict = h.rank(1, 4);
  ASSERT_EQ(strict.size(), 1u);
  EXPECT_EQ(strict[0].object, 2);
  EXPECT_THROW(h.rank(4), UsageError);
}

TEST(ObjectRanking, JsonAndCsvRows) {
  const HandGaussians h;
  const auto l1 = h.rank(1);
  const nlohmann::json rows = object_ranking_json(hand_table(), l1, 2);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["rank"], 1);
  EXPECT_EQ(rows[0]["id"], "A");
  EXPECT_EQ(rows[0]["class"], "window");
  EXPECT_EQ(rows[0]["building"], "B");
  EXPECT_EQ(rows[1]["id"], "win,\"C\"");
  const std::string csv = object_ranking_csv(hand_table(), l1);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "rank,id,class,level,building,part,gaussians,mean_score,max_score,above_threshold");
  EXPECT_NE(csv.find("\n2,\"win,\"\"C\"\"\",window,1,B,,3,"), std::string::npos) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
}

}  // namespace
}  // namespace cls
