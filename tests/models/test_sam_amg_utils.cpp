// AMG utilities (utils/amg.py semantics) on hand-computed cases and the fixtures' crop layout.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/sam_amg/amg_geometry.h"
#include "models/sam_amg/automatic_mask_generator.h"
#include "models/sam_amg/box_nms.h"
#include "models/sam_amg/mask_rle.h"
#include "models/sam_amg/small_regions.h"
#include "sam_amg_test_util.h"
#include <algorithm>
#include <cmath>
#include <vector>

using namespace cls::amg;

namespace {
BinaryMask from_rows(const std::vector<std::string>& rows) {
  BinaryMask m(static_cast<int>(rows.size()), static_cast<int>(rows[0].size()));
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) m.pixels[static_cast<size_t>(y) * m.width + x] = rows[y][x] == '#';
  return m;
}
}  // namespace

TEST(SamAmgUtils, RleColumnMajorWithLeadingZeroRun) {
  // Column-major order: column 0 = (1, 0), column 1 = (1, 1), column 2 = (0, 1).
  const BinaryMask m = from_rows({"##.", ".##"});
  const MaskRle rle = mask_to_rle(m);
  EXPECT_EQ(rle.counts, (std::vector<uint32_t>{0, 1, 1, 2, 1, 1}));  // 1 0 | 1 1 | 0 1
  EXPECT_EQ(area_from_rle(rle), 4);
  EXPECT_EQ(rle_to_mask(rle).pixels, m.pixels);
  EXPECT_EQ(mask_to_rle(BinaryMask(2, 3)).counts, (std::vector<uint32_t>{6}));
  MaskRle bad = rle;
  bad.counts.push_back(1);
  EXPECT_THROW(rle_to_mask(bad), cls::Error);
}

TEST(SamAmgUtils, MaskToBoxInclusiveAndEmpty) {
  const BoxXyxy b = mask_to_box(from_rows({"....", ".#..", "...#"}));
  EXPECT_EQ(b, (BoxXyxy{1, 1, 3, 2}));
  EXPECT_EQ(mask_to_box(BinaryMask(3, 3)), (BoxXyxy{0, 0, 0, 0}));
}

TEST(SamAmgUtils, BoxNmsTorchvisionSemantics) {
  const std::vector<BoxF> boxes = {{0, 0, 10, 10}, {0, 5, 10, 15}, {20, 20, 30, 30}, {20, 20, 30, 30}};
  // IoU(0, 1) = 50 / 150 = 1/3.
  EXPECT_EQ(box_nms(boxes, {0.9f, 0.8f, 0.5f, 0.5f}, 0.3), (std::vector<int>{0, 2}));
  EXPECT_EQ(box_nms(boxes, {0.9f, 0.8f, 0.5f, 0.5f}, 1.0 / 3.0 + 1e-6), (std::vector<int>{0, 1, 2}));
  // Ties resolve to the lower index (stable sort): box 2 beats its duplicate 3.
  EXPECT_EQ(box_nms(boxes, {0.1f, 0.2f, 0.7f, 0.7f}, 0.7), (std::vector<int>{2, 1, 0}));
  // Equal to the threshold is kept (suppression needs IoU > threshold): IoU of 0 vs 4 is 0.5.
  const std::vector<BoxF> half = {{0, 0, 10, 10}, {0, 0, 10, 5}};
  EXPECT_EQ(box_nms(half, {1.0f, 0.5f}, 0.5), (std::vector<int>{0, 1}));
  EXPECT_EQ(box_nms(half, {1.0f, 0.5f}, 0.49), (std::vector<int>{0}));
}

TEST(SamAmgUtils, CropBoxesAndGridsMatchFixture) {
  const auto j = nlohmann::json::parse(cls::read_text_file(amg_test::amg_fixture("strict_records.json")));
  // The run's own image size and parameters.
  const auto& params = j["params"];
  const int n_layers = params["crop_n_layers"].get<int>(), n = params["points_per_side"].get<int>();
  const auto crops = generate_crop_boxes(j["image_hw"][0].get<int>(), j["image_hw"][1].get<int>(), n_layers,
                                         params["crop_overlap_ratio"].get<double>());
  const auto expected = j["crop_boxes_xyxy"];
  ASSERT_EQ(crops.size(), expected.size());
  for (size_t i = 0; i < crops.size(); ++i) {
    EXPECT_EQ((std::vector<int>{crops[i].x0, crops[i].y0, crops[i].x1, crops[i].y1}), expected[i].get<std::vector<int>>());
    EXPECT_EQ(crops[i].layer, j["crop_layer_idxs"][i].get<int>());
  }
  const auto grids = build_all_layer_point_grids(n, n_layers, params["crop_n_points_downscale_factor"].get<int>());
  ASSERT_EQ(grids.size(), static_cast<size_t>(n_layers + 1));
  ASSERT_EQ(grids.size(), j["point_grid_sizes"].size());
  for (size_t l = 0; l < grids.size(); ++l)
    EXPECT_EQ(static_cast<int>(grids[l].size()), j["point_grid_sizes"][l].get<int>()) << "layer " << l;
  const double offset = 1.0 / (2 * n);
  EXPECT_EQ(grids[0][0], (Point2d{offset, offset}));
  EXPECT_EQ(grids[0][1][1], offset);  // x varies fastest
  EXPECT_DOUBLE_EQ(grids[0][n - 1][0], 1.0 - offset);
  EXPECT_EQ(build_all_layer_point_grids(32, 2, 2)[2].size(), 64u);  // hand case: int(32 / 2^2) = 8 per side
}

// The generator hands the model its points in the model's input frame, whatever that side is (the reference's
// SamPredictor.transform is ResizeLongestSide(img_size)): a model of input side 512 and a portrait image of
// 403 x 302 (h x w) scale 512 / 403, so the grid's last point ((1 - 1/(2n)) of each side) lands at
// (1 - 1/(2n)) * 384 and (1 - 1/(2n)) * 512. No IoU passes, so nothing is upsampled.
TEST(SamAmgUtils, PointsReachTheModelInItsInputFrame) {
  class RecordingModel : public AmgModel {
   public:
    void set_image(const uint8_t*, int, int) override {}
    int input_size() const override { return 512; }
    void predict_points(const std::vector<Point2d>& points, std::vector<float>& ious) override {
      seen.insert(seen.end(), points.begin(), points.end());
      ious.assign(points.size() * 3, 0.0f);
    }
    void upsample_masks(const std::vector<int64_t>&, std::vector<float>&) override { ADD_FAILURE() << "no mask passes"; }
    std::vector<Point2d> seen;
  } model;
  AmgParams params;
  params.points_per_side = 4;
  params.crop_n_layers = 0;
  const int h = 403, w = 302;
  const std::vector<uint8_t> rgb(static_cast<size_t>(h) * w * 3, 128);
  const MaskLevels levels = generate_masks(model, rgb.data(), h, w, params, 1);
  for (const auto& level : levels) EXPECT_TRUE(level.empty());
  ASSERT_EQ(model.seen.size(), 16u);
  double max_x = 0, max_y = 0;
  for (const Point2d& p : model.seen) max_x = std::max(max_x, p[0]), max_y = std::max(max_y, p[1]);
  EXPECT_NEAR(max_x, (1.0 - 1.0 / 8) * 384.0, 1e-9);
  EXPECT_NEAR(max_y, (1.0 - 1.0 / 8) * 512.0, 1e-9);
}

TEST(SamAmgUtils, NearCropEdge) {
  const CropBox crop{150, 100, 403, 302, 1};  // right and bottom edges are image edges
  // Left edge of the box at crop x 20 -> |170 - 150| = 20 <= 20: near the crop's left edge.
  EXPECT_TRUE(is_box_near_crop_edge({20, 50, 60, 80}, crop, 302, 403));
  EXPECT_FALSE(is_box_near_crop_edge({21, 50, 60, 80}, crop, 302, 403));
  // Touching the crop's right edge, which is also the image edge: not filtered.
  EXPECT_FALSE(is_box_near_crop_edge({30, 30, 252, 201}, crop, 302, 403));
  // Whole-image crop: nothing is near a crop edge that is not an image edge.
  EXPECT_FALSE(is_box_near_crop_edge({0, 0, 402, 301}, CropBox{0, 0, 403, 302, 0}, 302, 403));
}

TEST(SamAmgUtils, StabilityScore) {
  const std::vector<float> logits = {2.0f, 1.0f, 0.5f, -0.5f, -1.0f, -3.0f};
  // > 1: one value; > -1: four values.
  EXPECT_FLOAT_EQ(stability_score(logits.data(), 2, 3, 0.0f, 1.0f), 0.25f);
  const std::vector<float> low(4, -5.0f);
  EXPECT_TRUE(std::isnan(stability_score(low.data(), 2, 2, 0.0f, 1.0f)));
}

TEST(SamAmgUtils, RemoveSmallRegions) {
  // A 6x6 block with a 1-pixel hole and a separate 2-pixel island (8-connected diagonal pair).
  BinaryMask m = from_rows({"######....",
                            "######....",
                            "##.###....",
                            "######....",
                            "######...#",
                            "######..#."});
  BinaryMask holes = m;
  EXPECT_TRUE(remove_small_regions(holes, 3, SmallRegionMode::Holes));
  EXPECT_EQ(holes.at(2, 2), 1);
  EXPECT_EQ(holes.at(0, 9), 0);  // the big background region is untouched
  BinaryMask islands = holes;
  EXPECT_TRUE(remove_small_regions(islands, 3, SmallRegionMode::Islands));
  EXPECT_EQ(islands.at(4, 9), 0);
  EXPECT_EQ(islands.at(5, 8), 0);  // diagonal neighbour: same 8-connected island, removed
  EXPECT_EQ(islands.area(), 36);
  BinaryMask clean = islands;
  EXPECT_FALSE(remove_small_regions(clean, 3, SmallRegionMode::Holes));
  EXPECT_FALSE(remove_small_regions(clean, 3, SmallRegionMode::Islands));
  // All islands small: the largest survives.
  BinaryMask specks = from_rows({"#...##", "......", "......"});
  EXPECT_TRUE(remove_small_regions(specks, 5, SmallRegionMode::Islands));
  EXPECT_EQ(specks.area(), 2);
  EXPECT_EQ(specks.at(0, 4), 1);
}

TEST(SamAmgUtils, SmallRegionPostprocessPrefersUnchangedMasks) {
  // Two near-identical masks; the first needs a hole filled (score 0), the second is clean (score 1):
  // NMS keeps the clean one first, the changed one is suppressed (IoU > 0.7).
  BinaryMask clean(20, 20);
  for (int y = 2; y < 15; ++y)
    for (int x = 2; x < 15; ++x) clean.pixels[y * 20 + x] = 1;
  BinaryMask holed = clean;
  holed.pixels[8 * 20 + 8] = 0;
  AmgCandidate a, b, c;
  a.rle = mask_to_rle(holed), a.box = mask_to_box(holed), a.predicted_iou = 0.9f;
  b.rle = mask_to_rle(clean), b.box = mask_to_box(clean), b.predicted_iou = 0.8f;
  BinaryMask far(20, 20);
  far.pixels[18 * 20 + 18] = 1;  // a lone pixel: all islands small, it stays
  c.rle = mask_to_rle(far), c.box = mask_to_box(far), c.predicted_iou = 0.7f;
  const auto out = postprocess_small_regions({a, b, c}, 4, 0.7);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].predicted_iou, 0.8f);
  EXPECT_EQ(out[1].predicted_iou, 0.7f);
}
