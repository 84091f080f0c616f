// LangSplat post-processing (masks_update / mask_nms, seg map) against the SAM fixtures: the
// reference AMG records go in, the reference post-processing results must come out.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

#include "core/atomic_file.h"
#include "core/npy.h"
#include "models/sam_amg/langsplat_post.h"
#include "models/sam_amg/records_json.h"
#include "sam_amg_test_util.h"

using namespace cls::amg;
using amg_test::amg_fixture;

namespace {

nlohmann::json read_json(const std::string& path) { return nlohmann::json::parse(cls::read_text_file(path)); }

void check_post_run(const std::string& run, MaskNmsMethod method) {
  const MaskLevels records = read_levels_file(amg_fixture(run + "_records.json"));
  const nlohmann::json post = read_json(amg_fixture(run + "_post.json"));
  const MasksUpdateResult result = masks_update(records, amg_test::post_params(post), method);
  const MaskLevels expected = levels_from_json(post["levels"], run + "_post.json");
  for (int l = 0; l < kNumLevels; ++l) {
    SCOPED_TRACE(run + " level " + level_name(l));
    EXPECT_EQ(result.selected[l], post["mask_nms_selected_idx"][level_name(l)].get<std::vector<int>>());
    EXPECT_EQ(result.kept[l], post["kept_input_indices"][level_name(l)].get<std::vector<int>>());
    ASSERT_EQ(result.levels[l].size(), expected[l].size());
    for (size_t i = 0; i < expected[l].size(); ++i)
      EXPECT_EQ(result.levels[l][i].segmentation.counts, expected[l][i].segmentation.counts) << i;
  }

  // Seg map: LangSplat's <image>_s.npy, identical pixel for pixel.
  const cls::NpyArray npy = cls::read_npy(amg_fixture(run + "_seg_map.npy"));
  ASSERT_EQ(npy.shape.size(), 3u);
  const SegMap map = build_seg_map(result.levels, static_cast<int>(npy.shape[1]), static_cast<int>(npy.shape[2]));
  const float* ref = npy.as<float>();
  EXPECT_EQ(std::vector<int>(map.level_lengths.begin(), map.level_lengths.end()),
            post["seg_map_level_lengths"].get<std::vector<int>>());
  ASSERT_EQ(static_cast<int64_t>(map.values.size()), npy.numel());
  size_t differing = 0;
  for (size_t i = 0; i < map.values.size(); ++i) differing += static_cast<float>(map.values[i]) != ref[i];
  EXPECT_EQ(differing, 0u);
}

}  // namespace

TEST(SamAmgPost, RelaxedMatchesReferenceFast) { check_post_run("relaxed", MaskNmsMethod::Fast); }
TEST(SamAmgPost, StrictMatchesReferenceFast) { check_post_run("strict", MaskNmsMethod::Fast); }
TEST(SamAmgPost, RelaxedMatchesReferenceSlowReference) { check_post_run("relaxed", MaskNmsMethod::Reference); }
TEST(SamAmgPost, StrictMatchesReferenceTorch) { check_post_run("strict", MaskNmsMethod::Torch); }

TEST(SamAmgPost, FixtureRecordsAreConsistent) {
  // RLE decode/encode round trip, area_from_rle and the box of the decoded mask vs the record.
  for (const char* run : {"relaxed", "strict"}) {
    const MaskLevels levels = read_levels_file(amg_fixture(std::string(run) + "_records.json"));
    for (int l = 0; l < kNumLevels; ++l)
      for (const MaskRecord& r : levels[l]) {
        const BinaryMask m = rle_to_mask(r.segmentation);
        EXPECT_EQ(mask_to_rle(m).counts, r.segmentation.counts);
        EXPECT_EQ(area_from_rle(r.segmentation), r.area);
        EXPECT_EQ(m.area(), r.area);
        const BoxXyxy b = mask_to_box(m);
        EXPECT_EQ((std::array<int64_t, 4>{b.x0, b.y0, b.x1 - b.x0, b.y1 - b.y0}), r.bbox);
      }
  }
}

namespace {
// Random blobs (ellipses), some nested, some duplicated, one empty: exercises IoU, both
// containment branches and ties.
std::vector<BinaryMask> random_masks(int n, int h, int w, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<BinaryMask> masks;
  for (int k = 0; k < n; ++k) {
    if (k > 2 && u(rng) < 0.2) {  // near-copy or shrunken copy of an earlier mask
      BinaryMask m = masks[static_cast<size_t>(u(rng) * masks.size())];
      for (auto& p : m.pixels)
        if (u(rng) < 0.1) p = 0;
      masks.push_back(m);
      continue;
    }
    BinaryMask m(h, w);
    if (k != 5) {
      const double cx = u(rng) * w, cy = u(rng) * h, rx = 2 + u(rng) * w / 3, ry = 2 + u(rng) * h / 3;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          m.pixels[static_cast<size_t>(y) * w + x] =
              ((x - cx) * (x - cx) / (rx * rx) + (y - cy) * (y - cy) / (ry * ry)) <= 1.0;
    }
    masks.push_back(m);
  }
  return masks;
}
}  // namespace

TEST(SamAmgMaskNms, FastAndTorchEqualReferenceOnRandomMasks) {
  std::mt19937 rng(7);
  size_t kept_total = 0, input_total = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const int n = 20 + 15 * trial, h = 61 + trial, w = 130 - 7 * trial;  // widths across word edges
    const auto masks = random_masks(n, h, w, rng);
    std::vector<double> scores(n);
    std::uniform_real_distribution<double> u(0.5, 1.0);
    for (auto& s : scores) s = u(rng);
    scores[3] = scores[4];  // a tie
    for (const MaskNmsParams& p : {MaskNmsParams{}, MaskNmsParams{0.5, 0.6, 0.2}, MaskNmsParams{0.9, 0.99, 0.5}}) {
      const auto ref = mask_nms_reference(masks, scores, p);
      std::vector<PackedMask> packed;
      for (const auto& m : masks) packed.push_back(pack_mask(m));
      EXPECT_EQ(mask_nms_fast(packed, scores, p, 1), ref);
      EXPECT_EQ(mask_nms_fast(packed, scores, p, 3), ref);
      EXPECT_EQ(mask_nms_torch(masks, scores, p), ref);
      kept_total += ref.size();
      input_total += masks.size();
    }
  }
  // The cases have teeth: masks are kept and masks are suppressed.
  EXPECT_GT(kept_total, input_total / 10);
  EXPECT_LT(kept_total, input_total / 2);
}

TEST(SamAmgMaskNms, HandComputedContainment) {
  // 10x10 image. A: all of it (area 100), B: 3x3 inside A (area 9), C: 2x2 in a corner, away from B.
  BinaryMask a(10, 10), b(10, 10), c(10, 10);
  std::fill(a.pixels.begin(), a.pixels.end(), 1);
  for (int y = 2; y < 5; ++y)
    for (int x = 2; x < 5; ++x) b.pixels[y * 10 + x] = 1;
  for (int y = 8; y < 10; ++y)
    for (int x = 8; x < 10; ++x) c.pixels[y * 10 + x] = 1;
  // B in A: I/A_A = 0.09 < 0.5, I/A_B = 1 >= 0.85 -> inner[A, B] = 1 - 0.09 = 0.91 > 0.5: B dropped.
  // Same for C (inner 0.96). A survives (nothing earlier; inner_l of A: pairs where A is inside a
  // later mask: none). IoU(A, B) = 0.09.
  const std::vector<BinaryMask> masks = {b, a, c};
  const std::vector<double> scores = {0.9, 0.95, 0.8};
  EXPECT_EQ(mask_nms_reference(masks, scores, {}), std::vector<int>({1}));
  // With inner_thr 0.01 the limit is 0.99: both small masks survive; order by score.
  EXPECT_EQ(mask_nms_reference(masks, scores, {0.8, 0.7, 0.01}), std::vector<int>({1, 0, 2}));
  // A mask inside a *later* (lower-score) bigger one is dropped too (the tril branch): with A
  // scored last, B and C still go (without that branch the result would be {0, 2, 1}).
  const std::vector<double> scores2 = {0.9, 0.75, 0.8};
  EXPECT_EQ(mask_nms_reference(masks, scores2, {}), std::vector<int>({1}));
  std::vector<PackedMask> packed = {pack_mask(b), pack_mask(a), pack_mask(c)};
  EXPECT_EQ(mask_nms_fast(packed, scores2, {}), std::vector<int>({1}));
  EXPECT_EQ(mask_nms_torch(masks, scores2, {}), std::vector<int>({1}));
  // Score threshold: nobody above 0.99 -> LangSplat's intended top-3 fallback keeps the top 3.
  EXPECT_EQ(mask_nms_reference(masks, scores, {0.8, 0.99, 0.01}), std::vector<int>({1, 0, 2}));
}
